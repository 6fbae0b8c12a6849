// Brassel and Reif's Thiessen procedure; see thiessen_sweep.h for the outline.
//
// Notation. The centroid being processed is A. A "site" is a centroid (its index in the x-sorted
// order, >= 0) or one of A's four dummy points (kLeft .. kTop, < 0), i.e. A's reflection in that
// side. Since the bisector of any centroid and its own reflection is the side itself, a record
// entry that names a dummy means "the side" for every centroid, and vertices found by one centroid
// can be entered in the records of others.
//
// Orientation. Walking clockwise around A, the polygon side shared with neighbour `in` ends at a
// vertex, where the side shared with neighbour `out` begins. At a vertex whose circle carries the
// sites c_0 .. c_{m-1} in anticlockwise order around the circle, site c_i has in = c_{i-1} and
// out = c_{i+1}:
//
//              c_{i+1} (out)
//             /
//     c_i ---V          walking clockwise around c_i: in the side with c_{i-1}, out along
//             \         the side with c_{i+1}; any other c_j on the circle meets c_i only at V
//              c_{i-1} (in)
//
// The search from X = in finds every site on the circle in E1 at once (the potential neighbour
// and its ties), so a vertex is created once, with all its sites, and each unprocessed centroid
// among them gets its (in, out) entry.

#include "thiessen_sweep.h"

#include "circumcentre.h"
#include "errors.h"
#include "polygon_area.h"
#include "predicates.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace tessera
{
namespace
{

constexpr std::int32_t kLeft = -1;
constexpr std::int32_t kRight = -2;
constexpr std::int32_t kBottom = -3;
constexpr std::int32_t kTop = -4;
constexpr std::int32_t kNone = std::numeric_limits<std::int32_t>::min();
constexpr double kUnit = 0x1p-53;

struct Box
{
  double XLo, XHi, YLo, YHi;
};

// A disk containing an exact circle (centre and radius already widened for rounding).
struct Disk
{
  double X = 0.0, Y = 0.0, R = std::numeric_limits<double>::infinity();
};

constexpr Box kEverything = { -std::numeric_limits<double>::infinity(),
  std::numeric_limits<double>::infinity(),
  -std::numeric_limits<double>::infinity(),
  std::numeric_limits<double>::infinity() };

// A bounding box of the circle through A and the offsets b, c from A (each carrying a relative
// error below kUnit), widened by a bound on every rounding error made here, so that it contains
// the exact circle.
// Returns false when no such bound is reliable (nearly collinear points, extreme magnitudes):
// the caller then keeps the range it has (at worst, no range: a full scan).
bool CircleBox(double ax,
  double ay,
  double bx,
  double by,
  double cx,
  double cy,
  Box& box,
  Disk& disk)
{
  // The bounds below are tuned for offsets of about unit size (their absolute terms, the limits
  // 1e-70 .. 1e70): offsets of another size are scaled by a power of two, which is exact, and the
  // box scaled back (a cluster 1e-80 wide in a window of 1 gave up here, and each search scanned
  // every point: 50 s for 5000 points).
  const double larger =
    std::max(std::max(std::fabs(bx), std::fabs(by)), std::max(std::fabs(cx), std::fabs(cy)));
  double up = 1.0, down = 1.0;
  if (!(larger > 0x1p-60 && larger < 0x1p60))
  {
    const int k = std::ilogb(larger);
    if (!(std::isfinite(larger) && larger > 0.0 && k > -1000 && k < 1000))
    {
      return false;
    }
    up = std::ldexp(1.0, -k);
    down = std::ldexp(1.0, k);
    bx *= up, by *= up, cx *= up, cy *= up;
  }
  const double bmax = std::max(std::fabs(bx), std::fabs(by));
  const double cmax = std::max(std::fabs(cx), std::fabs(cy));
  if (!(bmax > 1e-70 && bmax < 1e70 && cmax > 1e-70 && cmax < 1e70))
  {
    return false;
  }
  const double b2 = bx * bx + by * by;
  const double c2 = cx * cx + cy * cy;
  const double p1 = bx * cy, p2 = by * cx;
  const double d = 2.0 * (p1 - p2);
  const double absD = std::fabs(d);
  // Error bounds of d and the numerators, inputs' own errors included (generous constants).
  const double errD = 8.0 * kUnit * 2.0 * (std::fabs(p1) + std::fabs(p2)) + 1e-300;
  if (!(absD > 4.0 * errD))
  {
    return false;
  }
  const double nx = cy * b2 - by * c2;
  const double ny = bx * c2 - cx * b2;
  const double errNx = 12.0 * kUnit * (std::fabs(cy) * b2 + std::fabs(by) * c2) + 1e-300;
  const double errNy = 12.0 * kUnit * (std::fabs(bx) * c2 + std::fabs(cx) * b2) + 1e-300;
  // |n/d - n'/d'| <= (err(n) / |d| + |n / d| rD) / (1 - rD) with rD = err(d) / |d| <= 1/4, plus
  // the roundings of the reciprocal and the product (2 units of |v|).
  const double inverse = 1.0 / d;
  const double vx = nx * inverse;
  const double vy = ny * inverse;
  const double absInverse = std::fabs(inverse);
  const double rD = errD * absInverse;
  const double grow = 1.0 / (1.0 - rD) + 4.0 * kUnit;
  const double ex = (errNx * absInverse + std::fabs(vx) * rD) * grow + 2.0 * kUnit * std::fabs(vx);
  const double ey = (errNy * absInverse + std::fabs(vy) * rD) * grow + 2.0 * kUnit * std::fabs(vy);
  const double r = std::sqrt(vx * vx + vy * vy);
  // The exact centre is within ex, ey of (vx, vy) and the exact radius within ex + ey (+ the
  // rounding of r) of r: half-widths r + 2 (ex + ey) contain the exact circle; doubled for safety.
  const double half = r * (1.0 + 8.0 * kUnit) + 4.0 * (ex + ey);
  // Scaled back (exact, but for a result among the subnormals: `tiny` covers its rounding).
  const double tiny = down == 1.0 ? 0.0 : 8.0 * std::numeric_limits<double>::denorm_min();
  const double xlo = (vx - half) * down - tiny, xhi = (vx + half) * down + tiny;
  const double ylo = (vy - half) * down - tiny, yhi = (vy + half) * down + tiny;
  const double slackX = 4.0 * kUnit * (std::fabs(ax) + std::max(std::fabs(xlo), std::fabs(xhi)));
  const double slackY = 4.0 * kUnit * (std::fabs(ay) + std::max(std::fabs(ylo), std::fabs(yhi)));
  box = { ax + xlo - slackX, ax + xhi + slackX, ay + ylo - slackY, ay + yhi + slackY };
  disk = { ax + vx * down, ay + vy * down, half * down + tiny + std::max(slackX, slackY) };
  return std::isfinite(box.XLo) && std::isfinite(box.XHi) && std::isfinite(box.YLo) &&
    std::isfinite(box.YHi);
}

class Sweep
{
public:
  Sweep(double xmin,
    double xmax,
    double ymin,
    double ymax,
    std::vector<double> xs,
    std::vector<double> ys,
    std::vector<std::int32_t> ids);

  /// Sweeps every centroid; progress (if any) as ComputeThiessenSweep's.
  void Run(const std::function<bool(double)>& progress);

  // Results. Every Thiessen vertex is stored once, in Vertices; tiles refer to them by index.
  std::vector<Point2> Vertices;
  // Completed tiles, in processing order: a record per tile, and its vertex indices
  // (anticlockwise) and neighbour ids (across the side after each vertex; -1 for the window),
  // written once while the tile is in cache; the output gathers them in id order.
  struct TileRecord
  {
    std::int64_t Start = 0; ///< into PackedVertexIds and PackedNeighbors
    double Area = 0.0;
    std::int32_t Size = 0;
    SweepSearchCounts Counts;
  };
  std::vector<TileRecord> Records; // per x-sorted index
  std::vector<std::int32_t> PackedVertexIds;
  std::vector<std::int32_t> PackedNeighbors;
  std::vector<std::pair<std::int32_t, std::int32_t>> Kind1; // half-neighbours, x-sorted indices
  std::size_t DegenerateVertices = 0;

  const std::vector<std::int32_t>& Ids() const { return this->IdOf; }

private:
  struct StripPoint
  {
    double Y, X;
    std::int32_t S; ///< x-sorted index
  };
  struct Entry
  {
    std::int32_t In, Out, Vertex, Next;
  };

  void BuildIndex();
  void ProcessCentroid(std::int32_t a);
  std::int32_t NearestCentroid(std::int32_t a);
  Entry SearchAndRecord(std::int32_t cur);
  void SearchNext(std::int32_t cur);
  struct Cursor
  {
    std::int32_t Strip;
    std::int32_t Begin, End; ///< the strip's positions
    std::int32_t Up, Down;   ///< next positions to visit above and below A's ordinate
    double YLo, YHi;         ///< ordinates of the range within the strip's abscissae
    std::uint32_t Version;   ///< RangeVersion the limits were computed for
  };
  Cursor MakeCursor(std::int32_t strip);
  void LimitCursor(Cursor& c);
  bool StepCursor(Cursor& c);
  void Visit(const StripPoint& point);
  void ConsiderPoint(std::int32_t q, const Point2& pq);
  void Consider(std::int32_t q);
  std::int32_t LowerBound(std::int32_t begin, std::int32_t end, double y) const;
  static int OrientDummyPoint(std::int32_t dummy, const Point2& a, const Point2& q);
  void UpdateBox();
  void AddRecord(std::int32_t c, std::int32_t in, std::int32_t out, std::int32_t vertex);
  Point2 FaceCentre(const std::vector<std::int32_t>& circle) const;

  // Sites relative to A.
  void ApproxOffset(std::int32_t s, double& ox, double& oy) const;
  Offset2 ExactOffset(std::int32_t s) const;
  int Orient(std::int32_t s1, std::int32_t s2) const; // orient2d(A, s1, s2)
  int InCircle(std::int32_t q) const;                 // q inside the circle (A, Cur, P)?

  double XMin, XMax, YMin, YMax;
  std::vector<double> Xs, Ys;
  std::vector<std::int32_t> IdOf;
  std::int32_t M;

  // Bucket index: strips of about StripSize consecutive x-sorted centroids (never splitting a set
  // of equal abscissae: a column of points is one strip), each sorted by y.
  std::int32_t StripSize = 1;
  std::vector<std::int32_t> StripBegin; // StripCount + 1 entries
  std::vector<std::int32_t> StripOf;    // per x-sorted index
  std::int32_t StripCount = 0;
  std::vector<double> StripXLo, StripXHi, StripYLo, StripYHi;
  std::vector<StripPoint> Strip;             // strip by strip, each sorted by y
  std::vector<std::int32_t> PositionInStrip; // per x-sorted index: its place in its strip
  // Per x-sorted index: where its ordinate falls in the strips on its left and right (the first
  // position whose ordinate is not smaller), so that most scans need no binary search.
  std::vector<std::int32_t> PositionLeft, PositionRight;
  // Per polygon: where A's ordinate falls in the strips scanned so far (saves binary searches),
  // by strip, valid where StripStartStamp holds the polygon's StartStamp. (A list searched
  // linearly made a polygon whose searches walk many strips quadratic in them: points on two
  // horizontal lines, 57% of the time.)
  std::vector<std::int32_t> StripStartPosition;
  std::vector<std::uint32_t> StripStartStamp;
  std::uint32_t StartStamp = 0;
  std::int32_t StripStart(std::int32_t strip);
  void NewStripStarts();
  void SetStripStart(std::int32_t strip, std::int32_t position);

  // Neighbour records.
  std::vector<Entry> Pool;
  std::int32_t FreeEntry = -1;
  std::vector<std::int32_t> Head;
  std::vector<std::uint8_t> Processed;

  // The current polygon and search.
  std::int32_t A = 0;
  Point2 PA;
  std::int32_t Cur = 0;
  std::int32_t P = kNone;
  Point2 PCur, PP; // coordinates of Cur and P when they are centroids
  std::vector<std::int32_t> Ties;
  Box Range = kEverything;
  Disk Bound;                     // a disk holding the circle's E1 part (infinite: none yet)
  std::uint32_t RangeVersion = 0; // changes with Range and Bound
  SweepSearchCounts* Count = nullptr;
  std::vector<Entry> Known, Cycle;
  std::vector<Cursor> Cursors;
  std::vector<std::int32_t> Members, Circle;
  std::vector<Point2> Polygon;
};

Sweep::Sweep(double xmin,
  double xmax,
  double ymin,
  double ymax,
  std::vector<double> xs,
  std::vector<double> ys,
  std::vector<std::int32_t> ids)
  : XMin(xmin)
  , XMax(xmax)
  , YMin(ymin)
  , YMax(ymax)
  , Xs(std::move(xs))
  , Ys(std::move(ys))
  , IdOf(std::move(ids))
  , M(static_cast<std::int32_t>(this->Xs.size()))
{
}

void Sweep::ApproxOffset(std::int32_t s, double& ox, double& oy) const
{
  // Each component is the rounded exact offset (relative error below kUnit), as CircleBox needs.
  switch (s)
  {
    case kLeft:
      ox = 2.0 * (this->XMin - this->PA.x);
      oy = 0.0;
      return;
    case kRight:
      ox = 2.0 * (this->XMax - this->PA.x);
      oy = 0.0;
      return;
    case kBottom:
      ox = 0.0;
      oy = 2.0 * (this->YMin - this->PA.y);
      return;
    case kTop:
      ox = 0.0;
      oy = 2.0 * (this->YMax - this->PA.y);
      return;
    default:
      ox = this->Xs[s] - this->PA.x;
      oy = this->Ys[s] - this->PA.y;
  }
}

Offset2 Sweep::ExactOffset(std::int32_t s) const
{
  if (s >= 0)
  {
    return exact_offset(Point2{ this->Xs[s], this->Ys[s] }, this->PA);
  }
  // Twice the exact offset of A from the side: the reflection, exactly.
  Offset2 o;
  if (s == kLeft || s == kRight)
  {
    const Offset2 d =
      exact_offset(Point2{ s == kLeft ? this->XMin : this->XMax, 0.0 }, Point2{ this->PA.x, 0.0 });
    o.x = 2.0 * d.x;
    o.xTail = 2.0 * d.xTail;
  }
  else
  {
    const Offset2 d = exact_offset(
      Point2{ 0.0, s == kBottom ? this->YMin : this->YMax }, Point2{ 0.0, this->PA.y });
    o.y = 2.0 * d.y;
    o.yTail = 2.0 * d.yTail;
  }
  return o;
}

int Sweep::OrientDummyPoint(std::int32_t dummy, const Point2& a, const Point2& q)
{
  // orient2d(a, dummy, q): the dummy's offset from a is axis-parallel, so the sign is a product
  // of exact comparisons.
  const int dy = (q.y > a.y) - (q.y < a.y);
  const int dx = (q.x > a.x) - (q.x < a.x);
  switch (dummy)
  {
    case kLeft:
      return -dy; // offset (-, 0): cross = ox * (qy - ay)
    case kRight:
      return dy;
    case kBottom:
      return dx; // offset (0, -): cross = -oy * (qx - ax)
    default:
      return -dx;
  }
}

std::int32_t Sweep::LowerBound(std::int32_t begin, std::int32_t end, double y) const
{
  return static_cast<std::int32_t>(std::lower_bound(this->Strip.begin() + begin,
                                     this->Strip.begin() + end,
                                     y,
                                     [](const StripPoint& p, double v) { return p.Y < v; }) -
    this->Strip.begin());
}

int Sweep::Orient(std::int32_t s1, std::int32_t s2) const
{
  if (s1 >= 0 && s2 >= 0)
  {
    return orient2d_fast(
      this->PA, Point2{ this->Xs[s1], this->Ys[s1] }, Point2{ this->Xs[s2], this->Ys[s2] });
  }
  if (s1 < 0 && s2 >= 0)
  {
    return OrientDummyPoint(s1, this->PA, Point2{ this->Xs[s2], this->Ys[s2] });
  }
  if (s1 >= 0 && s2 < 0)
  {
    return -this->Orient(s2, s1);
  }
  return cross_sign(this->ExactOffset(s1), this->ExactOffset(s2));
}

int Sweep::InCircle(std::int32_t q) const
{
  // Inside the circle through A, Cur, P (P clockwise of A->Cur): incircle(A, P, Cur, q) > 0.
  if (q >= 0 && this->P >= 0 && this->Cur >= 0)
  {
    return incircle_fast(this->PA,
      Point2{ this->Xs[this->P], this->Ys[this->P] },
      Point2{ this->Xs[this->Cur], this->Ys[this->Cur] },
      Point2{ this->Xs[q], this->Ys[q] });
  }
  // incircle(A, P, Cur, q) = -incircle(P, Cur, q, A) (a cyclic shift of four is odd).
  return -incircle_offsets(
    this->ExactOffset(this->P), this->ExactOffset(this->Cur), this->ExactOffset(q));
}

void Sweep::BuildIndex()
{
  // About sqrt(M) strips of sqrt(M) centroids: a circle spanning a few point spacings then meets
  // a couple of strips and a few points in each.
  this->StripSize =
    std::max<std::int32_t>(4, static_cast<std::int32_t>(std::sqrt(double(this->M))));
  this->StripBegin.assign(1, 0);
  while (this->StripBegin.back() < this->M)
  {
    std::int32_t end = std::min(this->M, this->StripBegin.back() + this->StripSize);
    while (end < this->M && this->Xs[end] == this->Xs[end - 1])
    {
      ++end;
    }
    this->StripBegin.push_back(end);
  }
  this->StripCount = static_cast<std::int32_t>(this->StripBegin.size()) - 1;
  this->StripOf.resize(this->M);
  for (std::int32_t s = 0; s < this->StripCount; ++s)
  {
    std::fill(this->StripOf.begin() + this->StripBegin[s],
      this->StripOf.begin() + this->StripBegin[s + 1],
      s);
  }
  this->StripXLo.resize(this->StripCount);
  this->StripXHi.resize(this->StripCount);
  this->StripYLo.resize(this->StripCount);
  this->StripYHi.resize(this->StripCount);
  this->Strip.resize(this->M);
  this->PositionInStrip.resize(this->M);
  for (std::int32_t s = 0; s < this->StripCount; ++s)
  {
    const std::int32_t begin = this->StripBegin[s];
    const std::int32_t end = this->StripBegin[s + 1];
    this->StripXLo[s] = this->Xs[begin];
    this->StripXHi[s] = this->Xs[end - 1];
    for (std::int32_t k = begin; k < end; ++k)
    {
      this->Strip[k] = { this->Ys[k], this->Xs[k], k };
    }
    std::sort(this->Strip.begin() + begin,
      this->Strip.begin() + end,
      [](const StripPoint& p, const StripPoint& q)
      { return p.Y < q.Y || (p.Y == q.Y && p.S < q.S); });
    for (std::int32_t k = begin; k < end; ++k)
    {
      this->PositionInStrip[this->Strip[k].S] = k;
    }
    this->StripYLo[s] = this->Strip[begin].Y;
    this->StripYHi[s] = this->Strip[end - 1].Y;
  }
  // Merge each pair of adjacent strips once (both sorted by y) to place every point in its
  // neighbours.
  this->PositionLeft.assign(this->M, 0);
  this->PositionRight.assign(this->M, 0);
  for (std::int32_t s = 0; s + 1 < this->StripCount; ++s)
  {
    const std::int32_t aBegin = this->StripBegin[s], aEnd = this->StripBegin[s + 1];
    const std::int32_t bBegin = aEnd, bEnd = this->StripBegin[s + 2];
    std::int32_t j = bBegin;
    for (std::int32_t i = aBegin; i < aEnd; ++i)
    {
      while (j < bEnd && this->Strip[j].Y < this->Strip[i].Y)
      {
        ++j;
      }
      this->PositionRight[this->Strip[i].S] = j;
    }
    j = aBegin;
    for (std::int32_t i = bBegin; i < bEnd; ++i)
    {
      while (j < aEnd && this->Strip[j].Y < this->Strip[i].Y)
      {
        ++j;
      }
      this->PositionLeft[this->Strip[i].S] = j;
    }
  }
}

void Sweep::AddRecord(std::int32_t c, std::int32_t in, std::int32_t out, std::int32_t vertex)
{
  std::int32_t e = this->FreeEntry;
  if (e >= 0)
  {
    this->FreeEntry = this->Pool[e].Next;
  }
  else
  {
    e = static_cast<std::int32_t>(this->Pool.size());
    this->Pool.push_back({});
  }
  this->Pool[e] = { in, out, vertex, this->Head[c] };
  this->Head[c] = e;
}

void Sweep::Run(const std::function<bool(double)>& progress)
{
  this->BuildIndex();
  this->Head.assign(this->M, -1);
  this->Processed.assign(this->M, 0);
  this->Records.assign(this->M, TileRecord{});
  this->PackedVertexIds.reserve(std::size_t(this->M) * 6 + 8);
  this->PackedNeighbors.reserve(std::size_t(this->M) * 6 + 8);
  this->Vertices.reserve(std::size_t(this->M) * 2 + 8);
  if (this->M == 0)
  {
    return;
  }

  // The centroid nearest the lower-left corner V0 goes first; V0 is one of its vertices, between
  // its sides on the bottom (in) and on the left (out), unless another centroid is as near.
  const Point2 v0{ this->XMin, this->YMin };
  std::int32_t first = 0;
  bool unique = true;
  for (std::int32_t s = 1; s < this->M; ++s)
  {
    const int c = compare_distance_fast(
      v0, Point2{ this->Xs[s], this->Ys[s] }, Point2{ this->Xs[first], this->Ys[first] });
    if (c < 0)
    {
      first = s;
      unique = true;
    }
    else if (c == 0)
    {
      unique = false;
    }
  }
  if (unique)
  {
    this->Vertices.push_back(v0);
    this->AddRecord(first, kBottom, kLeft, 0);
  }
  this->ProcessCentroid(first);
  for (std::int32_t s = 0; s < this->M; ++s)
  {
    if (progress && s % 64 == 0 && !progress(static_cast<double>(s) / this->M))
    {
      throw Cancelled();
    }
    if (s != first)
    {
      this->ProcessCentroid(s);
    }
  }
}

std::int32_t Sweep::NearestCentroid(std::int32_t a)
{
  // Any nearest centroid N shares a side of positive length with A: the midpoint of AN is nearer
  // to A and N than to any other centroid, and inside the (convex) window.
  std::int32_t best = kNone;
  double reach = std::numeric_limits<double>::infinity();
  const Point2 pa{ this->Xs[a], this->Ys[a] };
  auto visit = [&](std::int32_t q)
  {
    if (q == a)
    {
      return;
    }
    const Point2 pq{ this->Xs[q], this->Ys[q] };
    if (best == kNone ||
      compare_distance_fast(pa, pq, Point2{ this->Xs[best], this->Ys[best] }) < 0)
    {
      best = q;
      const double dx = pq.x - pa.x, dy = pq.y - pa.y;
      // (hypot where the squares underflow or overflow: points 1e-200 apart had a reach of
      // 1e-300, which missed their nearest centroid, and the sweep failed with a logic_error)
      const double squares = dx * dx + dy * dy;
      const double distance =
        squares > 1e-280 && squares < 1e280 ? std::sqrt(squares) : std::hypot(dx, dy);
      reach = distance * (1.0 + 1e-9) + 1e-300;
    }
  };
  const std::int32_t s0 = this->StripOf[a];
  auto scan = [&](std::int32_t s)
  {
    const std::int32_t begin = this->StripBegin[s];
    const std::int32_t end = this->StripBegin[s + 1];
    std::int32_t up = this->LowerBound(begin, end, pa.y);
    std::int32_t down = up - 1;
    while (up < end || down >= begin)
    {
      if (up < end)
      {
        if (this->Strip[up].Y - pa.y <= reach)
        {
          if (std::fabs(this->Strip[up].X - pa.x) <= reach)
          {
            visit(this->Strip[up].S);
          }
          ++up;
        }
        else
        {
          up = end;
        }
      }
      if (down >= begin)
      {
        if (pa.y - this->Strip[down].Y <= reach)
        {
          if (std::fabs(this->Strip[down].X - pa.x) <= reach)
          {
            visit(this->Strip[down].S);
          }
          --down;
        }
        else
        {
          down = begin - 1;
        }
      }
    }
  };
  scan(s0);
  std::int32_t lo = s0 - 1, hi = s0 + 1;
  bool goLeft = true, goRight = true;
  while (goLeft || goRight)
  {
    if (goRight)
    {
      if (hi < this->StripCount && this->StripXLo[hi] - pa.x <= reach)
      {
        scan(hi++);
      }
      else
      {
        goRight = false;
      }
    }
    if (goLeft)
    {
      if (lo >= 0 && pa.x - this->StripXHi[lo] <= reach)
      {
        scan(lo--);
      }
      else
      {
        goLeft = false;
      }
    }
  }
  return best;
}

void Sweep::UpdateBox()
{
  // The circle through A, Cur and any point of E1 contains, on the E1 side, the circle of the
  // final answer: so every such box is a valid range, and so is their intersection.
  double bx, by, cx, cy;
  this->ApproxOffset(this->Cur, bx, by);
  this->ApproxOffset(this->P, cx, cy);
  Box box;
  Disk disk;
  if (CircleBox(this->PA.x, this->PA.y, bx, by, cx, cy, box, disk))
  {
    this->Range.XLo = std::max(this->Range.XLo, box.XLo);
    this->Range.XHi = std::min(this->Range.XHi, box.XHi);
    this->Range.YLo = std::max(this->Range.YLo, box.YLo);
    this->Range.YHi = std::min(this->Range.YHi, box.YHi);
    // (the disk's tests square distances: a radius below 1e-100 could underflow them, and a
    // search missed its answer; the box alone serves such small circles)
    if (disk.R < this->Bound.R && disk.R > 1e-100)
    {
      this->Bound = disk;
    }
    ++this->RangeVersion;
  }
}

void Sweep::Consider(std::int32_t q)
{
  if (this->P == kNone)
  {
    this->P = q;
    this->UpdateBox();
    return;
  }
  const int inside = this->InCircle(q);
  if (inside > 0)
  {
    ++this->Count->InCircle;
    this->P = q;
    this->Ties.clear();
    this->UpdateBox();
  }
  else if (inside == 0)
  {
    // Fig. 5: on the circle, a tie. Any of the ties gives the same circle, and they are sorted
    // round it once the search ends (the paper kept the less clockwise as P: no need).
    ++this->Count->InCircle;
    this->Ties.push_back(q);
  }
}

void Sweep::ConsiderPoint(std::int32_t q, const Point2& pq)
{
  if (this->P == kNone)
  {
    this->P = q;
    this->PP = pq;
    this->UpdateBox();
    return;
  }
  const int inside =
    this->Cur >= 0 ? incircle_fast(this->PA, this->PP, this->PCur, pq) : this->InCircle(q);
  if (inside > 0)
  {
    ++this->Count->InCircle;
    this->P = q;
    this->PP = pq;
    this->Ties.clear();
    this->UpdateBox();
  }
  else if (inside == 0)
  {
    // Fig. 5: on the circle, a tie (as in Consider).
    ++this->Count->InCircle;
    this->Ties.push_back(q);
  }
}

inline void Sweep::Visit(const StripPoint& point)
{
  const std::int32_t q = point.S;
  if (q == this->A || q == this->Cur)
  {
    return;
  }
  ++this->Count->Consulted;
  // Abscissa range of the circle, then half-plane E1 (strictly clockwise of A -> Cur).
  if (point.X < this->Range.XLo || point.X > this->Range.XHi)
  {
    return;
  }
  const Point2 pq{ point.X, point.Y };
  const int side = this->Cur >= 0 ? orient2d_fast(this->PA, this->PCur, pq)
                                  : OrientDummyPoint(this->Cur, this->PA, pq);
  if (side >= 0)
  {
    return;
  }
  ++this->Count->PassedTests;
  this->ConsiderPoint(q, pq);
}

std::int32_t Sweep::StripStart(std::int32_t strip)
{
  if (this->StripStartStamp[strip] == this->StartStamp)
  {
    return this->StripStartPosition[strip];
  }
  const std::int32_t begin = this->StripBegin[strip];
  const std::int32_t end = this->StripBegin[strip + 1];
  const std::int32_t position = this->LowerBound(begin, end, this->PA.y);
  this->SetStripStart(strip, position);
  return position;
}

void Sweep::NewStripStarts()
{
  if (this->StripStartStamp.size() != static_cast<std::size_t>(this->StripCount))
  {
    this->StripStartStamp.assign(this->StripCount, 0);
    this->StripStartPosition.assign(this->StripCount, 0);
    this->StartStamp = 0;
  }
  if (++this->StartStamp == 0) // (wrapped: no stale stamp may match)
  {
    std::fill(this->StripStartStamp.begin(), this->StripStartStamp.end(), 0u);
    this->StartStamp = 1;
  }
}

void Sweep::SetStripStart(std::int32_t strip, std::int32_t position)
{
  this->StripStartStamp[strip] = this->StartStamp;
  this->StripStartPosition[strip] = position;
}

Sweep::Cursor Sweep::MakeCursor(std::int32_t strip)
{
  Cursor c;
  c.Strip = strip;
  c.Begin = this->StripBegin[strip];
  c.End = this->StripBegin[strip + 1];
  c.Version = this->RangeVersion - 1;
  // A strip whose points all lie on one vertical or horizontal segment (collinear input, a
  // lattice column) is skipped when the segment is in the closed side E2 of A -> Cur: none of its
  // points can be in E1.
  const double xlo = this->StripXLo[strip], xhi = this->StripXHi[strip];
  const double ylo = this->StripYLo[strip], yhi = this->StripYHi[strip];
  // A strip whose bounding box misses the bounding disk holds no candidate (generous slack: this
  // only prunes).
  const Disk& d = this->Bound;
  if (d.R < std::numeric_limits<double>::infinity())
  {
    const double dx = d.X < xlo ? xlo - d.X : (d.X > xhi ? d.X - xhi : 0.0);
    const double dy = d.Y < ylo ? ylo - d.Y : (d.Y > yhi ? d.Y - yhi : 0.0);
    if (dx * dx + dy * dy > d.R * d.R * (1.0 + 1e-9))
    {
      c.Up = c.End;
      c.Down = c.Begin - 1;
      return c;
    }
  }
  if (xlo == xhi || ylo == yhi)
  {
    const Point2 ends[2] = { { xlo, ylo }, { xhi, yhi } };
    bool outside = true;
    for (const Point2& e : ends)
    {
      const int side = this->Cur >= 0 ? orient2d_fast(this->PA, this->PCur, e)
                                      : OrientDummyPoint(this->Cur, this->PA, e);
      outside = outside && side >= 0;
    }
    if (outside)
    {
      c.Up = c.End;
      c.Down = c.Begin - 1;
      return c;
    }
  }
  c.Up = this->StripStart(strip);
  c.Down = c.Up - 1;
  return c;
}

void Sweep::LimitCursor(Cursor& c)
{
  // The range's ordinates, narrowed to the chord of the bounding disk over the strip's abscissae
  // (a strip the circle only grazes gets a short range). Computed with generous relative slack:
  // it is a pruning bound, exact decisions come later.
  c.Version = this->RangeVersion;
  c.YLo = this->Range.YLo;
  c.YHi = this->Range.YHi;
  const Disk& d = this->Bound;
  if (!(d.R < std::numeric_limits<double>::infinity()))
  {
    return;
  }
  const double xlo = this->StripXLo[c.Strip], xhi = this->StripXHi[c.Strip];
  if (this->StripYLo[c.Strip] == this->StripYHi[c.Strip])
  {
    // All the strip's points on one horizontal line (sorted by x there): keep the chord of the
    // disk along that line.
    const double dy = std::fabs(this->StripYLo[c.Strip] - d.Y) * (1.0 - 1e-12);
    if (dy > d.R)
    {
      c.Up = c.End;
      c.Down = c.Begin - 1;
      return;
    }
    const double w = std::sqrt((d.R - dy) * (d.R + dy)) * (1.0 + 1e-12);
    const double slack = 1e-12 * (std::fabs(d.X) + w);
    const double from = d.X - w - slack, to = d.X + w + slack;
    auto byX = [](const StripPoint& p, double v) { return p.X < v; };
    const std::int32_t first = static_cast<std::int32_t>(
      std::lower_bound(this->Strip.begin() + c.Begin, this->Strip.begin() + c.End, from, byX) -
      this->Strip.begin());
    const std::int32_t last =
      static_cast<std::int32_t>(std::upper_bound(this->Strip.begin() + c.Begin,
                                  this->Strip.begin() + c.End,
                                  to,
                                  [](double v, const StripPoint& p) { return v < p.X; }) -
        this->Strip.begin());
    c.Begin = first;
    c.End = last;
    c.Up = std::max(c.Up, first);
    c.Down = std::min(c.Down, last - 1);
    return;
  }
  double dx = d.X < xlo ? xlo - d.X : (d.X > xhi ? d.X - xhi : 0.0);
  dx *= 1.0 - 1e-12;
  if (dx > d.R)
  {
    c.YLo = std::numeric_limits<double>::infinity();
    c.YHi = -std::numeric_limits<double>::infinity();
    return;
  }
  const double h = std::sqrt((d.R - dx) * (d.R + dx)) * (1.0 + 1e-12);
  const double slack = 1e-12 * (std::fabs(d.Y) + h);
  c.YLo = std::max(c.YLo, d.Y - h - slack);
  c.YHi = std::min(c.YHi, d.Y + h + slack);
  // The chord need not contain A's ordinate, where the cursor started: skip to the chord.
  if (c.Up < c.End && this->Strip[c.Up].Y < c.YLo)
  {
    c.Up = this->LowerBound(c.Up, c.End, c.YLo);
  }
  if (c.Down >= c.Begin && this->Strip[c.Down].Y > c.YHi)
  {
    c.Down = static_cast<std::int32_t>(std::upper_bound(this->Strip.begin() + c.Begin,
                                         this->Strip.begin() + c.Down + 1,
                                         c.YHi,
                                         [](double v, const StripPoint& p) { return v < p.Y; }) -
               this->Strip.begin()) -
      1;
  }
}

bool Sweep::StepCursor(Cursor& c)
{
  // One point up and one point down from A's ordinate, while inside the (shrinking) range. (An
  // exhausted cursor first: limiting one cost two binary searches for nothing.)
  if (c.Up >= c.End && c.Down < c.Begin)
  {
    return false;
  }
  if (c.Version != this->RangeVersion)
  {
    this->LimitCursor(c);
  }
  bool visited = false;
  if (c.Up < c.End)
  {
    if (this->Strip[c.Up].Y <= c.YHi)
    {
      this->Visit(this->Strip[c.Up++]);
      visited = true;
    }
    else
    {
      c.Up = c.End;
    }
  }
  if (c.Down >= c.Begin)
  {
    if (this->Strip[c.Down].Y >= c.YLo)
    {
      this->Visit(this->Strip[c.Down--]);
      visited = true;
    }
    else
    {
      c.Down = c.Begin - 1;
    }
  }
  return visited;
}

void Sweep::SearchNext(std::int32_t cur)
{
  this->Cur = cur;
  if (cur >= 0)
  {
    this->PCur = Point2{ this->Xs[cur], this->Ys[cur] };
  }
  this->P = kNone;
  this->Ties.clear();
  this->Range = kEverything;
  this->Bound = Disk{};
  ++this->RangeVersion;
  ++this->Count->Searches;
  // The dummies in E1 (there is always one). The paper starts from one of them as the first
  // potential neighbour; here their circles first only bound the range (a dummy's circle is
  // large for a centroid far from the border), the centroids are searched, and the dummies are
  // tested last, exactly like any point. The result is the same: the sites on the smallest circle
  // (P and its ties, sorted round it afterwards), whatever the order of the tests.
  std::int32_t dummies[4];
  int dummyCount = 0;
  for (const std::int32_t d : { kLeft, kBottom, kRight, kTop })
  {
    if (d == cur)
    {
      continue;
    }
    ++this->Count->Consulted;
    if (this->Orient(cur, d) < 0)
    {
      ++this->Count->PassedTests;
      dummies[dummyCount++] = d;
    }
  }
  if (dummyCount == 0)
  {
    throw std::logic_error("Brassel-Reif sweep: no dummy point in the clockwise half-plane");
  }
  // Until a first centroid of E1 is found there is no range: step outward in A's strip, and
  // widen to the neighbouring strips round by round (A's strip may hold none: a lattice column
  // when Cur is straight above A). After two rounds the dummies' circles bound the range, so that
  // a centroid with no point of E1 nearby does not scan everything.
  const std::int32_t s0 = this->StripOf[this->A];
  this->Cursors.assign(1, this->MakeCursor(s0));
  std::int32_t lo = s0, hi = s0;
  bool bounded = false;
  auto bound = [&]()
  {
    for (int k = 0; k < dummyCount; ++k)
    {
      this->P = dummies[k];
      this->UpdateBox();
    }
    this->P = kNone;
    bounded = true;
  };
  for (int round = 1; this->P == kNone; ++round)
  {
    bool visited = false;
    for (std::size_t k = 0; k < this->Cursors.size() && this->P == kNone;)
    {
      Cursor& c = this->Cursors[k];
      visited = this->StepCursor(c) || visited;
      if (c.Up >= c.End && c.Down < c.Begin)
      {
        c = this->Cursors.back(); // exhausted: drop it
        this->Cursors.pop_back();
      }
      else
      {
        ++k;
      }
    }
    if (this->P != kNone)
    {
      break;
    }
    bool widened = false;
    if (hi + 1 < this->StripCount && this->StripXLo[hi + 1] <= this->Range.XHi)
    {
      this->Cursors.push_back(this->MakeCursor(++hi));
      widened = true;
    }
    if (lo > 0 && this->StripXHi[lo - 1] >= this->Range.XLo)
    {
      this->Cursors.push_back(this->MakeCursor(--lo));
      widened = true;
    }
    if (!bounded && (round >= 2 || (!visited && !widened)))
    {
      bound();
    }
    else if (!visited && !widened)
    {
      break; // no centroid of E1 within the dummies' circles
    }
  }
  // With a potential neighbour: finish the strips begun, then go outward, alternately right and
  // left, while the strips meet the abscissa range.
  for (std::size_t k = 0; k < this->Cursors.size(); ++k)
  {
    while (this->StepCursor(this->Cursors[k]))
    {
    }
  }
  bool goLeft = true, goRight = true;
  while (goLeft || goRight)
  {
    if (goRight)
    {
      if (hi + 1 < this->StripCount && this->StripXLo[hi + 1] <= this->Range.XHi)
      {
        Cursor c = this->MakeCursor(++hi);
        while (this->StepCursor(c))
        {
        }
      }
      else
      {
        goRight = false;
      }
    }
    if (goLeft)
    {
      if (lo > 0 && this->StripXHi[lo - 1] >= this->Range.XLo)
      {
        Cursor c = this->MakeCursor(--lo);
        while (this->StepCursor(c))
        {
        }
      }
      else
      {
        goLeft = false;
      }
    }
  }
  for (int k = 0; k < dummyCount; ++k)
  {
    if (this->P != kNone)
    {
      // A dummy outside the range is outside the circle: skip the exact test. (Its rounded
      // position is within an ulp or two of the exact reflection.)
      double ox, oy;
      this->ApproxOffset(dummies[k], ox, oy);
      const double x = this->PA.x + ox, y = this->PA.y + oy;
      const double margin =
        4.0 * kUnit * (std::fabs(x) + std::fabs(y) + std::fabs(ox) + std::fabs(oy));
      if (x < this->Range.XLo - margin || x > this->Range.XHi + margin ||
        y < this->Range.YLo - margin || y > this->Range.YHi + margin)
      {
        continue;
      }
    }
    this->Consider(dummies[k]);
  }
}

Point2 Sweep::FaceCentre(const std::vector<std::int32_t>& circle) const
{
  bool vertical = false, horizontal = false;
  double xSide = 0.0, ySide = 0.0;
  std::int32_t first[3] = { kNone, kNone, kNone }; // the first centroids by ComesFirst
  for (const std::int32_t s : circle)
  {
    if (s == kLeft || s == kRight)
    {
      vertical = true;
      xSide = s == kLeft ? this->XMin : this->XMax;
    }
    else if (s == kBottom || s == kTop)
    {
      horizontal = true;
      ySide = s == kBottom ? this->YMin : this->YMax;
    }
    else
    {
      std::int32_t c = s;
      for (std::int32_t& slot : first)
      {
        if (slot == kNone ||
          ComesFirst({ this->Xs[c], this->Ys[c] }, { this->Xs[slot], this->Ys[slot] }))
        {
          std::swap(slot, c);
          if (c == kNone)
          {
            break;
          }
        }
      }
    }
  }
  if (vertical && horizontal)
  {
    return { xSide, ySide }; // a window corner
  }
  const Point2 p{ this->Xs[first[0]], this->Ys[first[0]] };
  if (vertical || horizontal)
  {
    // Where the bisector of the first two centroids crosses the side.
    const Point2 q{ this->Xs[first[1]], this->Ys[first[1]] };
    if (vertical)
    {
      const double y =
        0.5 * (p.y + q.y) + (q.x - p.x) * ((xSide - p.x) + (xSide - q.x)) / (2.0 * (p.y - q.y));
      return { xSide, std::min(std::max(y, this->YMin), this->YMax) };
    }
    const double x =
      0.5 * (p.x + q.x) + (q.y - p.y) * ((ySide - p.y) + (ySide - q.y)) / (2.0 * (p.x - q.x));
    return { std::min(std::max(x, this->XMin), this->XMax), ySide };
  }
  // From the first three points by ComesFirst, as tiles.cpp computes it (circumcentre.h), so
  // that interior vertices get the same bits from both engines.
  return CircumcentreOf(p,
    Point2{ this->Xs[first[1]], this->Ys[first[1]] },
    Point2{ this->Xs[first[2]], this->Ys[first[2]] });
}

Sweep::Entry Sweep::SearchAndRecord(std::int32_t cur)
{
  this->SearchNext(cur);
  // The sites on the circle in E1, clockwise around A from Cur; then the circle anticlockwise:
  // A, the most clockwise (A's next neighbour), ..., the least clockwise, Cur.
  this->Members.assign(1, this->P);
  this->Members.insert(this->Members.end(), this->Ties.begin(), this->Ties.end());
  if (this->Members.size() > 1)
  {
    std::sort(this->Members.begin(),
      this->Members.end(),
      [this](std::int32_t s1, std::int32_t s2) { return this->Orient(s1, s2) < 0; });
  }
  this->Circle.assign(1, this->A);
  this->Circle.insert(this->Circle.end(), this->Members.rbegin(), this->Members.rend());
  this->Circle.push_back(cur);

  const std::int32_t vertex = static_cast<std::int32_t>(this->Vertices.size());
  this->Vertices.push_back(this->FaceCentre(this->Circle));
  const std::size_t m = this->Circle.size();
  bool dummies = false;
  for (std::size_t i = 1; i < m; ++i)
  {
    const std::int32_t c = this->Circle[i];
    if (c < 0)
    {
      dummies = true;
      continue;
    }
    if (this->Processed[c])
    {
      // That centroid's own search would have found this vertex and recorded it for A.
      throw std::logic_error("Brassel-Reif sweep: inconsistent vertex (point " +
        std::to_string(this->IdOf[c]) + " already completed)");
    }
    this->AddRecord(c, this->Circle[i - 1], this->Circle[(i + 1) % m], vertex);
  }
  if (m >= 4)
  {
    ++this->DegenerateVertices;
    if (!dummies)
    {
      // Sites not adjacent around the circle meet at this vertex only: half-neighbours.
      for (std::size_t i = 0; i < m; ++i)
      {
        for (std::size_t j = i + 2; j < m; ++j)
        {
          if (i == 0 && j == m - 1)
          {
            continue;
          }
          const std::int32_t p = this->Circle[i], q = this->Circle[j];
          this->Kind1.emplace_back(std::min(p, q), std::max(p, q));
        }
      }
    }
  }
  return Entry{ cur, this->Circle[1], vertex, -1 };
}

void Sweep::ProcessCentroid(std::int32_t a)
{
  this->A = a;
  this->PA = Point2{ this->Xs[a], this->Ys[a] };
  this->Count = &this->Records[a].Counts;
  this->Known.clear();
  for (std::int32_t e = this->Head[a]; e >= 0;)
  {
    const std::int32_t next = this->Pool[e].Next;
    this->Known.push_back(this->Pool[e]);
    this->Pool[e].Next = this->FreeEntry; // the record is dropped: its entries are recycled
    this->FreeEntry = e;
    e = next;
  }
  this->Head[a] = -1;
  {
    const std::int32_t strip = this->StripOf[a];
    this->NewStripStarts();
    this->SetStripStart(strip, this->PositionInStrip[a]);
    if (strip > 0)
    {
      this->SetStripStart(strip - 1, this->PositionLeft[a]);
    }
    if (strip + 1 < this->StripCount)
    {
      this->SetStripStart(strip + 1, this->PositionRight[a]);
    }
  }

  this->Cycle.clear();
  std::int32_t cur;
  std::int32_t firstVertex = -1;
  if (!this->Known.empty())
  {
    this->Cycle.push_back(this->Known.front());
    firstVertex = this->Known.front().Vertex;
    cur = this->Known.front().Out;
  }
  else
  {
    cur = this->M > 1 ? this->NearestCentroid(a) : kLeft;
  }
  const std::size_t limit = 16 + 4 * std::size_t(this->M);
  while (true)
  {
    const Entry* known = nullptr;
    for (const Entry& e : this->Known)
    {
      if (e.In == cur)
      {
        known = &e;
        break;
      }
    }
    if (known != nullptr)
    {
      if (known->Vertex == firstVertex)
      {
        break;
      }
      this->Cycle.push_back(*known);
      cur = known->Out;
    }
    else
    {
      const Entry found = this->SearchAndRecord(cur);
      if (firstVertex < 0)
      {
        firstVertex = found.Vertex;
        this->Known.push_back(found); // so that the walk recognises where it closes
      }
      this->Cycle.push_back(found);
      cur = found.Out;
    }
    if (this->Cycle.size() > limit)
    {
      throw std::logic_error("Brassel-Reif sweep: the polygon of point " +
        std::to_string(this->IdOf[a]) + " does not close");
    }
  }

  // The walk went clockwise: store anticlockwise. Vertex k is followed (anticlockwise) by the
  // side shared with the `in` neighbour of its entry.
  TileRecord& record = this->Records[a];
  record.Start = static_cast<std::int64_t>(this->PackedVertexIds.size());
  record.Size = static_cast<std::int32_t>(this->Cycle.size());
  this->Polygon.clear();
  for (std::size_t k = this->Cycle.size(); k-- > 0;)
  {
    const Entry& e = this->Cycle[k];
    this->PackedVertexIds.push_back(e.Vertex);
    this->PackedNeighbors.push_back(e.In >= 0 ? this->IdOf[e.In] : -1);
    this->Polygon.push_back(this->Vertices[e.Vertex]);
  }
  record.Area = CompensatedPolygonArea(this->Polygon.data(), this->Polygon.size());
  this->Processed[a] = 1;
}

/// Renumbers the corners' Thiessen vertices (ids below vertexCount) from 0 in the order they first
/// come, each group of vertices that some tile merged (pairs at one rounded point) as one.
void NumberCornerVertices(std::size_t vertexCount,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& merged,
  std::vector<std::int32_t>& corners)
{
  std::vector<std::int32_t> parent; // union-find over the merged vertices only (rare)
  const auto root = [&parent](std::int32_t v)
  {
    while (parent[v] != v)
    {
      v = parent[v] = parent[parent[v]];
    }
    return v;
  };
  if (!merged.empty())
  {
    parent.resize(vertexCount);
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& [kept, dropped] : merged)
    {
      const std::int32_t a = root(kept), b = root(dropped);
      parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<std::int32_t> number(vertexCount, -1);
  std::int32_t next = 0;
  for (std::int32_t& v : corners)
  {
    const std::int32_t r = parent.empty() ? v : root(v);
    if (number[r] < 0)
    {
      number[r] = next++;
    }
    v = number[r];
  }
}

/// Whether coefficient * coordinate + c is exactly 0 (coefficient in [1, 2) in magnitude, as a
/// window's sides have them), at any magnitude: fma gives the sum with one rounding, exact at 0,
/// once coordinate and c are scaled by one power of two near 1 (exactly: they are within a factor
/// of 4 of each other, or the sum cannot vanish), so that no product falls below the doubles'
/// range (a side at a subnormal coordinate was taken for one at a double).
bool LiesAt(double coefficient, double coordinate, double c)
{
  if (coordinate == 0.0 || c == 0.0)
  {
    return coordinate == 0.0 && c == 0.0;
  }
  const int ex = std::ilogb(coordinate), ec = std::ilogb(c);
  if (std::abs(ex - ec) > 2)
  {
    return false;
  }
  const int e = std::max(ex, ec);
  return std::fma(coefficient, std::ldexp(coordinate, -e), std::ldexp(c, -e)) == 0.0;
}

} // namespace

/// The sweep's border is the rectangle of the window's corners, which are doubles. A side given by
/// a constraint such as 3x - 1 < 0 lies at x = 1/3, which no double is: the border drawn at the
/// rounded corner would accept and reject points, and place Thiessen vertices, otherwise than the
/// window does (a point at the double nearest 1/3, strictly inside, was rejected), and the two
/// engines would disagree. So every corner must lie exactly on both its sides.
void CheckSidesAreDoubles(const Window& window)
{
  const std::vector<HalfPlane>& sides = window.EffectiveConstraints();
  const std::vector<Point2>& corners = window.Vertices();
  for (std::size_t k = 0; k < sides.size(); ++k)
  {
    // Edge k lies on constraint k and runs from corner k to corner k + 1.
    const HalfPlane& side = sides[k];
    const bool vertical = side.b == 0.0;
    for (const Point2& corner : { corners[k], corners[(k + 1) % corners.size()] })
    {
      if (vertical ? !LiesAt(side.a, corner.x, side.c) : !LiesAt(side.b, corner.y, side.c))
      {
        throw InputError("the Brassel-Reif sweep needs the window's sides at coordinates that are "
                         "doubles, and " +
          window.ConstraintName(window.EffectiveIds()[k]) + " puts one at " +
          (vertical ? "x = " : "y = ") + NumberText(-side.c / (vertical ? side.a : side.b)) +
          " (rounded), which no double is: give its coefficient as 1 or -1 (or a power of two), "
          "and the side's double as c, as WindowBounds gives its sides, or use the Green-Sibson "
          "engine");
      }
    }
  }
}

std::string WhyNotAnAxisAlignedRectangle(const Window& window)
{
  if (window.IsAxisAlignedRectangle())
  {
    return std::string();
  }
  const std::vector<HalfPlane>& sides = window.EffectiveConstraints();
  for (std::size_t k = 0; k < sides.size(); ++k)
  {
    const HalfPlane& h = sides[k];
    if (h.a != 0.0 && h.b != 0.0)
    {
      return window.ConstraintName(window.EffectiveIds()[k]) + " gives a slanted side";
    }
  }
  return "it has " + std::to_string(sides.size()) + " sides";
}

/// The largest coordinate the sweep works on: it reflects points across the window's sides
/// (2 side - p, its dummy points), which overflows beyond a quarter of the largest double.
constexpr double ReflectionReach = std::numeric_limits<double>::max() / 4;

/// Throws InputError naming the first point with a NaN or an infinite coordinate.
void CheckPointsAreFinite(const std::vector<Point2>& points)
{
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const Point2& p = points[i];
    if (std::isnan(p.x) || std::isnan(p.y))
    {
      throw InputError("point " + std::to_string(i) + " has a NaN coordinate");
    }
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
    {
      throw InputError("point " + std::to_string(i) + " has an infinite coordinate");
    }
  }
}

/// Whether p lies strictly inside the box (the window's own test: points on a side are rejected).
bool StrictlyInside(const Box2& box, const Point2& p)
{
  return box.XMin < p.x && p.x < box.XMax && box.YMin < p.y && p.y < box.YMax;
}

/// The power of two the sweep scales every coordinate by, for a window of these bounds. Working
/// at about unit scale changes no exact decision and no rounding (barring underflow and
/// overflow, checked), and keeps the floating-point ranges of the search effective; a window
/// reaching beyond a quarter of the largest double is scaled by a quarter, for its reflections.
/// 0 where the window or a point inside it would not scale exactly.
int SweepScale(const Box2& bounds, const std::vector<Point2>& points)
{
  int scale = 0;
  const double extent = bounds.LargerSide();
  if (std::isfinite(extent) && extent > 0.0)
  {
    const int e = std::ilogb(extent);
    scale = (e > 64 || e < -64) ? -e : 0;
  }
  const auto exactAt = [&](int s)
  {
    const auto exact = [s](double v) { return std::ldexp(std::ldexp(v, s), -s) == v; };
    bool ok = exact(bounds.XMin) && exact(bounds.XMax) && exact(bounds.YMin) && exact(bounds.YMax);
    // Only the points the sweep uses: a rejected one (say 1e-320 outside a window of 1e100)
    // kept the window unscaled, and every search a scan of all points (1500 times slower).
    for (std::size_t i = 0; i < points.size() && ok && s != 0; ++i)
    {
      const Point2& p = points[i];
      ok = !StrictlyInside(bounds, p) || (exact(p.x) && exact(p.y));
    }
    return ok;
  };
  // A window reaching beyond a quarter of the largest double (its sides wider than the doubles
  // reach, x from -9e307 to 9e307): a quarter of it is enough for the reflections below, and
  // loses no bit where scaling it to unit size would (y of 0.3 beside x of 9e307).
  const bool farReach = !(bounds.LargestMagnitude() < ReflectionReach);
  scale = exactAt(scale) ? scale : 0;
  if (farReach && scale > -2 && exactAt(-2))
  {
    scale = -2;
  }
  return scale;
}

ThiessenSweepResult ComputeThiessenSweep(const Window& window,
  const std::vector<Point2>& points,
  const std::function<bool(double)>& progress)
{
  const std::string notRectangle = WhyNotAnAxisAlignedRectangle(window);
  if (!notRectangle.empty())
  {
    throw InputError(
      "the Brassel-Reif sweep needs an axis-aligned rectangular window: " + notRectangle);
  }
  CheckSidesAreDoubles(window);
  const Box2 bounds = BoundsOf(window.Vertices().data(), window.Vertices().size());
  const double xmin = bounds.XMin, xmax = bounds.XMax, ymin = bounds.YMin, ymax = bounds.YMax;
  if (points.size() >= std::size_t(std::numeric_limits<std::int32_t>::max() / 4))
  {
    throw InputError(
      "too many points for the Brassel-Reif sweep: " + std::to_string(points.size()));
  }
  CheckPointsAreFinite(points);

  ThiessenSweepResult result;
  // Inside test exactly as the window's (strict); then sort by (x, y, id).
  struct Keyed
  {
    double X, Y;
    std::int32_t Id;
  };
  std::vector<Keyed> keyed;
  keyed.reserve(points.size());
  const int scale = SweepScale(bounds, points);
  const Box2 scaled{ std::ldexp(xmin, scale),
    std::ldexp(xmax, scale),
    std::ldexp(ymin, scale),
    std::ldexp(ymax, scale) };
  // (overflowing, the dummy points left the sweep without one, a logic_error)
  if (!(scaled.LargestMagnitude() < ReflectionReach))
  {
    throw InputError("the Brassel-Reif sweep reflects the points across the window's sides, "
                     "which overflows for a window reaching " +
      NumberText(bounds.LargestMagnitude()) +
      " (beyond some 4e307) that cannot be scaled down exactly with its points (numbers below "
      "some 1e-308 among them): scale them down (the filter vtkDirichletTessellation does)");
  }
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const Point2& p = points[i];
    if (StrictlyInside(bounds, p))
    {
      keyed.push_back(
        { std::ldexp(p.x, scale), std::ldexp(p.y, scale), static_cast<std::int32_t>(i) });
    }
    else
    {
      result.RejectedIds.push_back(static_cast<std::int32_t>(i));
    }
  }
  {
    // Bucket sort: buckets by abscissa (a monotone function of x), then each bucket sorted.
    auto less = [](const Keyed& p, const Keyed& q)
    { return p.X < q.X || (p.X == q.X && (p.Y < q.Y || (p.Y == q.Y && p.Id < q.Id))); };
    const std::size_t buckets =
      std::max<std::size_t>(1, std::min<std::size_t>(4096, keyed.size() / 64));
    // Keys are scaled by 2^scale, so the bucket range must be too.
    const double keyMin = scaled.XMin;
    const double keyMax = scaled.XMax;
    const double perUnit = double(buckets) / (keyMax - keyMin);
    auto bucketOf = [&](double x)
    {
      const double b = std::floor((x - keyMin) * perUnit);
      return b <= 0.0 ? std::size_t(0) : std::min(buckets - 1, std::size_t(b));
    };
    std::vector<std::size_t> start(buckets + 1, 0);
    for (const Keyed& k : keyed)
    {
      ++start[bucketOf(k.X) + 1];
    }
    for (std::size_t b = 0; b < buckets; ++b)
    {
      start[b + 1] += start[b];
    }
    std::vector<Keyed> sorted(keyed.size());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (const Keyed& k : keyed)
    {
      sorted[fill[bucketOf(k.X)]++] = k;
    }
    for (std::size_t b = 0; b < buckets; ++b)
    {
      std::sort(sorted.begin() + start[b], sorted.begin() + start[b + 1], less);
    }
    keyed.swap(sorted);
  }
  std::vector<double> xs, ys;
  std::vector<std::int32_t> ids;
  xs.reserve(keyed.size());
  ys.reserve(keyed.size());
  ids.reserve(keyed.size());
  for (const Keyed& k : keyed)
  {
    if (!ids.empty() && xs.back() == k.X && ys.back() == k.Y)
    {
      result.Duplicates.emplace_back(k.Id, ids.back());
      continue;
    }
    xs.push_back(k.X);
    ys.push_back(k.Y);
    ids.push_back(k.Id);
  }
  keyed = std::vector<Keyed>();
  std::sort(result.Duplicates.begin(), result.Duplicates.end());

  Sweep sweep(scaled.XMin,
    scaled.XMax,
    scaled.YMin,
    scaled.YMax,
    std::move(xs),
    std::move(ys),
    std::move(ids));
  sweep.Run(progress);
  result.VertexCount = sweep.Vertices.size();
  result.DegenerateVertexCount = sweep.DegenerateVertices;

  // Output in ascending id: gather each tile's packed record (prefetched ahead, since the
  // x-sorted and the id orders are unrelated) and append sequentially.
  const std::vector<std::int32_t>& idOf = sweep.Ids();
  const std::size_t accepted = idOf.size();
  std::vector<std::int32_t> sortedOf(points.size(), -1);
  for (std::size_t s = 0; s < accepted; ++s)
  {
    sortedOf[idOf[s]] = static_cast<std::int32_t>(s);
  }
  std::vector<std::pair<std::int32_t, std::int32_t>> half; // (i, j) ids, i < j, sorted
  half.reserve(sweep.Kind1.size());
  for (const auto& pair : sweep.Kind1)
  {
    const std::int32_t i = idOf[pair.first], j = idOf[pair.second];
    half.emplace_back(std::min(i, j), std::max(i, j));
  }
  std::sort(half.begin(), half.end());

  TileSet& tiles = result.Tiles;
  ContiguityGraph& graph = result.Contiguities;
  tiles.PointIds.reserve(accepted);
  tiles.Offsets.reserve(accepted + 1);
  tiles.Vertices.reserve(sweep.PackedVertexIds.size());
  tiles.Areas.reserve(accepted);
  tiles.NeighborCounts.reserve(accepted);
  result.Counts.reserve(accepted);
  graph.Pairs.reserve(sweep.PackedNeighbors.size() + 2 * half.size());
  graph.Kinds.reserve(sweep.PackedNeighbors.size() / 2 + half.size());
  tiles.Offsets.push_back(0);
  std::vector<std::pair<std::int32_t, std::uint8_t>> group;
  std::size_t nextHalf = 0;
  std::vector<std::int32_t> acceptedIds;
  acceptedIds.reserve(accepted);
  for (std::size_t id = 0; id < points.size(); ++id)
  {
    if (sortedOf[id] >= 0)
    {
      acceptedIds.push_back(static_cast<std::int32_t>(id));
    }
  }
  // Three stages of prefetching: a tile's record, then its vertex ids and neighbours, then its
  // vertices' coordinates.
  constexpr std::size_t kAhead = 4;
  const std::int32_t* vertexIds = sweep.PackedVertexIds.data();
  std::vector<Point2> polygon;                               // a tile's vertices (scratch)
  std::vector<std::int32_t> corners;                         // and the Thiessen vertex of each
  std::vector<std::pair<std::int32_t, std::int32_t>> merged; // vertices that round to one point
  result.CornerVertexIds.reserve(sweep.PackedVertexIds.size());
  for (std::size_t r = 0; r < accepted; ++r)
  {
    if (r + 3 * kAhead < accepted)
    {
      __builtin_prefetch(&sweep.Records[sortedOf[acceptedIds[r + 3 * kAhead]]]);
    }
    if (r + 2 * kAhead < accepted)
    {
      const auto& ahead = sweep.Records[sortedOf[acceptedIds[r + 2 * kAhead]]];
      __builtin_prefetch(vertexIds + ahead.Start);
      __builtin_prefetch(sweep.PackedNeighbors.data() + ahead.Start);
    }
    if (r + kAhead < accepted)
    {
      const auto& ahead = sweep.Records[sortedOf[acceptedIds[r + kAhead]]];
      for (std::int32_t k = 0; k < ahead.Size; ++k)
      {
        __builtin_prefetch(&sweep.Vertices[vertexIds[ahead.Start + k]]);
      }
    }
    const std::int32_t id = acceptedIds[r];
    const auto& record = sweep.Records[sortedOf[id]];
    tiles.PointIds.push_back(id);
    polygon.clear();
    corners.clear();
    for (std::int32_t k = 0; k < record.Size; ++k)
    {
      const Point2& v = sweep.Vertices[vertexIds[record.Start + k]];
      polygon.push_back(
        scale == 0 ? v : Point2{ std::ldexp(v.x, -scale), std::ldexp(v.y, -scale) });
      corners.push_back(vertexIds[record.Start + k]);
    }
    // Distinct Thiessen vertices can round to one point (the circumcentres of nearly co-circular
    // points, a window crossing within rounding of a corner): the polygon lists it once, as the
    // Green-Sibson engine's does, and the vertices are made one. Its area and NeighborCount (the
    // exact sides) stay as they are.
    if (HasRepeatedVertex(polygon))
    {
      DropRepeatedVertices(polygon, corners, &merged);
    }
    tiles.Vertices.insert(tiles.Vertices.end(), polygon.begin(), polygon.end());
    result.CornerVertexIds.insert(result.CornerVertexIds.end(), corners.begin(), corners.end());
    tiles.Offsets.push_back(static_cast<std::int64_t>(tiles.Vertices.size()));
    tiles.Areas.push_back(scale == 0 ? record.Area : std::ldexp(record.Area, -2 * scale));
    tiles.NeighborCounts.push_back(record.Size);
    result.Counts.push_back(record.Counts);
    group.clear();
    for (std::int32_t k = 0; k < record.Size; ++k)
    {
      const std::int32_t n = sweep.PackedNeighbors[record.Start + k];
      if (n > id)
      {
        group.emplace_back(n, 0);
      }
    }
    while (nextHalf < half.size() && half[nextHalf].first == id)
    {
      group.emplace_back(half[nextHalf++].second, 1);
    }
    std::sort(group.begin(), group.end());
    for (const auto& g : group)
    {
      graph.Pairs.push_back(id);
      graph.Pairs.push_back(g.first);
      graph.Kinds.push_back(g.second);
    }
  }
  NumberCornerVertices(sweep.Vertices.size(), merged, result.CornerVertexIds);
  return result;
}

} // namespace tessera
