#include "shared_borders.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace tessera
{
namespace
{

constexpr double ToleranceUlps = 64.0;

// A vertex to add inside an edge (the edge's start's index among all vertices), at parameter t.
struct Insertion
{
  std::size_t Edge;
  double T;
  Point2 Vertex;
};

double Tolerance(const Point2& a, const Point2& b)
{
  const double largest =
    std::max({ std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y) });
  return ToleranceUlps * (std::nextafter(largest, HUGE_VAL) - largest);
}

// The parameter along a -> b of v when v lies inside the edge (within tolerance of its line,
// farther than that from either end); otherwise a negative number.
double InsideParameter(const Point2& a, const Point2& b, const Point2& v)
{
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length = std::hypot(dx, dy);
  if (!(length > 0.0))
  {
    return -1.0;
  }
  const double wx = v.x - a.x, wy = v.y - a.y;
  const double along = (wx * dx + wy * dy) / length;
  const double off = std::fabs(wx * dy - wy * dx) / length;
  const double tolerance = Tolerance(a, b);
  if (off > tolerance || along <= tolerance || along >= length - tolerance)
  {
    return -1.0;
  }
  return along / length;
}

// A grid over the vertices' box whose cells list the edges whose boxes (widened by their
// tolerance) meet them: about one edge a cell.
class EdgeGrid
{
public:
  EdgeGrid(const ClippedRings& rings, const std::vector<std::size_t>& ringOf)
  {
    const std::vector<Point2>& v = rings.Vertices;
    for (const Point2& p : v)
    {
      this->Low = { std::min(this->Low.x, p.x), std::min(this->Low.y, p.y) };
      this->High = { std::max(this->High.x, p.x), std::max(this->High.y, p.y) };
    }
    this->Side = std::clamp(static_cast<int>(std::ceil(std::sqrt(double(v.size())))), 1, 1024);
    this->Starts.assign(std::size_t(this->Side) * this->Side + 1, 0);
    // Two passes: count each cell's edges, then fill them in (a flat array, cell by cell).
    for (int pass = 0; pass < 2; ++pass)
    {
      std::vector<std::size_t> next(this->Starts.begin(), this->Starts.end() - 1);
      for (std::size_t e = 0; e < v.size(); ++e)
      {
        const Point2& a = v[e];
        const Point2& b = v[NextVertex(rings, ringOf, e)];
        const double tolerance = Tolerance(a, b);
        int x0, y0, x1, y1;
        this->CellOf({ std::min(a.x, b.x) - tolerance, std::min(a.y, b.y) - tolerance }, x0, y0);
        this->CellOf({ std::max(a.x, b.x) + tolerance, std::max(a.y, b.y) + tolerance }, x1, y1);
        for (int y = y0; y <= y1; ++y)
        {
          for (int x = x0; x <= x1; ++x)
          {
            const std::size_t cell = std::size_t(y) * this->Side + x;
            if (pass == 0)
            {
              ++this->Starts[cell + 1];
            }
            else
            {
              this->Edges[next[cell]++] = e;
            }
          }
        }
      }
      if (pass == 0)
      {
        for (std::size_t c = 1; c < this->Starts.size(); ++c)
        {
          this->Starts[c] += this->Starts[c - 1];
        }
        this->Edges.resize(this->Starts.back());
      }
    }
  }

  static std::size_t NextVertex(const ClippedRings& rings,
    const std::vector<std::size_t>& ringOf,
    std::size_t e)
  {
    const std::size_t r = ringOf[e];
    return e + 1 < rings.RingOffsets[r + 1] ? e + 1 : rings.RingOffsets[r];
  }

  void CellOf(const Point2& p, int& x, int& y) const
  {
    x = Index(p.x, this->Low.x, this->High.x);
    y = Index(p.y, this->Low.y, this->High.y);
  }

  // The edges listed in the cell of p.
  const std::size_t* begin(const Point2& p) const
  {
    return this->Edges.data() + this->Starts[this->Cell(p)];
  }
  const std::size_t* end(const Point2& p) const
  {
    return this->Edges.data() + this->Starts[this->Cell(p) + 1];
  }

private:
  int Index(double c, double low, double high) const
  {
    const double width = high - low;
    if (!(width > 0.0))
    {
      return 0;
    }
    const double cell = std::floor((c - low) / width * this->Side);
    return static_cast<int>(std::clamp(cell, 0.0, double(this->Side - 1)));
  }

  std::size_t Cell(const Point2& p) const
  {
    int x, y;
    this->CellOf(p, x, y);
    return std::size_t(y) * this->Side + x;
  }

  Point2 Low{ HUGE_VAL, HUGE_VAL };
  Point2 High{ -HUGE_VAL, -HUGE_VAL };
  int Side = 1;
  std::vector<std::size_t> Starts;
  std::vector<std::size_t> Edges;
};

} // namespace

ClippedRings ShareBorderVertices(const ClippedRings& pieces)
{
  const std::vector<Point2>& v = pieces.Vertices;
  if (v.empty())
  {
    return pieces;
  }
  std::vector<std::size_t> ringOf(v.size());
  for (std::size_t r = 0; r + 1 < pieces.RingOffsets.size(); ++r)
  {
    std::fill(
      ringOf.begin() + pieces.RingOffsets[r], ringOf.begin() + pieces.RingOffsets[r + 1], r);
  }
  const EdgeGrid grid(pieces, ringOf);
  std::vector<Insertion> insertions;
  for (std::size_t k = 0; k < v.size(); ++k)
  {
    for (const std::size_t* e = grid.begin(v[k]); e != grid.end(v[k]); ++e)
    {
      if (ringOf[*e] == ringOf[k])
      {
        continue; // (a piece's own vertex is never inside its own edge: its ring is simple)
      }
      const double t = InsideParameter(v[*e], v[EdgeGrid::NextVertex(pieces, ringOf, *e)], v[k]);
      if (t > 0.0)
      {
        insertions.push_back({ *e, t, v[k] });
      }
    }
  }
  if (insertions.empty())
  {
    return pieces;
  }
  std::sort(insertions.begin(),
    insertions.end(),
    [](const Insertion& a, const Insertion& b)
    { return a.Edge != b.Edge ? a.Edge < b.Edge : a.T < b.T; });
  ClippedRings out;
  out.Vertices.reserve(v.size() + insertions.size());
  auto next = insertions.begin();
  for (std::size_t r = 0; r + 1 < pieces.RingOffsets.size(); ++r)
  {
    for (std::size_t k = pieces.RingOffsets[r]; k < pieces.RingOffsets[r + 1]; ++k)
    {
      out.Vertices.push_back(v[k]);
      for (; next != insertions.end() && next->Edge == k; ++next)
      {
        if (!(next->Vertex == out.Vertices.back())) // (the same point from two pieces: once)
        {
          out.Vertices.push_back(next->Vertex);
        }
      }
    }
    out.RingOffsets.push_back(out.Vertices.size());
  }
  return out;
}

void DensifyRingSymmetrically(const Point2* ring,
  std::size_t count,
  double step,
  std::vector<Point2>& out)
{
  out.clear();
  for (std::size_t k = 0; k < count; ++k)
  {
    const Point2& a = ring[k];
    const Point2& b = ring[(k + 1) % count];
    out.push_back(a);
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int pieces = step > 0.0 ? std::max(1, static_cast<int>(std::ceil(length / step))) : 1;
    const bool fromA = a.x < b.x || (a.x == b.x && a.y <= b.y);
    const Point2& p = fromA ? a : b;
    const Point2& q = fromA ? b : a;
    for (int i = 1; i < pieces; ++i)
    {
      const double t = static_cast<double>(fromA ? i : pieces - i) / pieces;
      out.push_back({ p.x + t * (q.x - p.x), p.y + t * (q.y - p.y) });
    }
  }
}

} // namespace tessera
