#include "meridian_cut.h"

#include "display_pieces.h" // CrossingHeight

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace tessera
{
namespace
{

/// Sutherland-Hodgman against one side of x = at (side -1: x <= at, +1: x >= at).
void AppendSide(const Point2* ring, std::size_t count, double at, double side, ClippedRings& out)
{
  const std::size_t start = out.Vertices.size();
  for (std::size_t i = 0; i < count; ++i)
  {
    const Point2& a = ring[i];
    const Point2& b = ring[i + 1 < count ? i + 1 : 0];
    const double da = side * (a.x - at), db = side * (b.x - at);
    if (da >= 0.0)
    {
      out.Vertices.push_back(a);
    }
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
    {
      out.Vertices.push_back({ at, CrossingHeight(a, b, at) }); // (the same from either side)
    }
  }
  if (out.Vertices.size() - start < 3)
  {
    out.Vertices.resize(start);
    return;
  }
  out.RingOffsets.push_back(out.Vertices.size());
}

/// Edges of a side's parts that run along x = at cut at every vertex of the side on the line
/// between their ends. Sutherland-Hodgman joins the stretches of a part on its side by edges along
/// the line (a bridge from where a piece leaves its side to where it comes back, a spike where a
/// piece touches the line along an edge), and neighbouring parts run along the same stretches
/// between other points: cut at the same points, such edges are walked once each way, piece by
/// piece, and cancel in OutlinesOfPieces.
///
///   part a: (at,0) -> (at,3)             cut at 1 and 2:  (at,0) -> (at,1) -> (at,2) -> (at,3)
///   part b: (at,2) -> (at,1) (its edge)  cancels           (at,1) -> (at,2)   <- cancelled
void CutEdgesOnTheLine(ClippedRings& side, double at)
{
  std::vector<double> heights; // the side's vertices on the line, by y
  for (const Point2& p : side.Vertices)
  {
    if (p.x == at)
    {
      heights.push_back(p.y);
    }
  }
  if (heights.size() < 3)
  {
    return; // (two points on the line: one edge, no point to cut it at)
  }
  std::sort(heights.begin(), heights.end());
  heights.erase(std::unique(heights.begin(), heights.end()), heights.end());
  ClippedRings cut;
  for (std::size_t r = 0; r + 1 < side.RingOffsets.size(); ++r)
  {
    const std::size_t begin = side.RingOffsets[r], end = side.RingOffsets[r + 1];
    for (std::size_t v = begin; v < end; ++v)
    {
      const Point2& a = side.Vertices[v];
      const Point2& b = side.Vertices[NextInRing(v, begin, end)];
      cut.Vertices.push_back(a);
      if (a.x != at || b.x != at || a.y == b.y)
      {
        continue;
      }
      const auto low = std::upper_bound(heights.begin(), heights.end(), std::min(a.y, b.y));
      const auto high = std::lower_bound(heights.begin(), heights.end(), std::max(a.y, b.y));
      if (a.y < b.y)
      {
        for (auto h = low; h != high; ++h)
        {
          cut.Vertices.push_back({ at, *h });
        }
      }
      else
      {
        for (auto h = high; h != low; --h)
        {
          cut.Vertices.push_back({ at, *(h - 1) });
        }
      }
    }
    cut.RingOffsets.push_back(cut.Vertices.size());
  }
  side = std::move(cut);
}

} // namespace

void SnapToMeridian(std::vector<Point2>& lonLat)
{
  const auto meridianNear = [](double lon)
  { return 180.0 + 360.0 * std::round((lon - 180.0) / 360.0); };
  const auto near = [&](const Point2& p)
  { return std::abs(p.x - meridianNear(p.x)) <= MeridianSnapDegrees; };
  if (std::all_of(lonLat.begin(), lonLat.end(), near))
  {
    return;
  }
  for (Point2& p : lonLat)
  {
    if (near(p))
    {
      p.x = meridianNear(p.x);
    }
  }
}

std::array<ClippedRings, 2> CutAtMeridian(const ClippedRings& pieces,
  std::size_t first,
  std::size_t last,
  double at)
{
  std::array<ClippedRings, 2> sides;
  for (std::size_t r = first; r < last; ++r)
  {
    const std::size_t begin = pieces.RingOffsets[r];
    const std::size_t count = pieces.RingOffsets[r + 1] - begin;
    AppendSide(&pieces.Vertices[begin], count, at, -1.0, sides[0]);
    AppendSide(&pieces.Vertices[begin], count, at, 1.0, sides[1]);
  }
  for (ClippedRings& side : sides)
  {
    CutEdgesOnTheLine(side, at);
  }
  return sides;
}

} // namespace tessera
