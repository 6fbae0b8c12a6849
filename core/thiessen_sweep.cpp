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

/// How far v lies outside [lo, hi] (0 inside).
double DistanceOutside(double v, double lo, double hi)
{
  return v < lo ? lo - v : (v > hi ? v - hi : 0.0);
}

// Scans strips outward from the strips [lo, hi] already scanned, alternately right and left, while
// the next one on a side meets the range: meetsRight(s) and meetsLeft(s) are asked before each
// strip, since the range shrinks as the scan goes.
template<class MeetsRight, class MeetsLeft, class Scan>
void ScanOutward(std::int32_t lo,
  std::int32_t hi,
  std::int32_t stripCount,
  const MeetsRight& meetsRight,
  const MeetsLeft& meetsLeft,
  const Scan& scan)
{
  bool goLeft = true, goRight = true;
  while (goLeft || goRight)
  {
    if (goRight)
    {
      goRight = hi + 1 < stripCount && meetsRight(hi + 1);
      if (goRight)
      {
        scan(++hi);
      }
    }
    if (goLeft)
    {
      goLeft = lo > 0 && meetsLeft(lo - 1);
      if (goLeft)
      {
        scan(--lo);
      }
    }
  }
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
  void CutStrips();
  void SortStrips();
  void PlaceInNeighbourStrips();
  void PlaceIn(std::int32_t from,
    std::int32_t fromEnd,
    std::int32_t to,
    std::int32_t toEnd,
    std::vector<std::int32_t>& position) const;
  std::int32_t NearestToCorner(const Point2& v, bool& unique) const;
  void ProcessCentroid(std::int32_t a);
  void TakeKnownEntries(std::int32_t a);
  void SeedStripStarts(std::int32_t a);
  void WalkClockwise(std::int32_t a);
  const Entry* KnownEntryFrom(std::int32_t in) const;
  void StoreTile(std::int32_t a);
  std::int32_t NearestCentroid(std::int32_t a) const;
  /// The nearest centroid to A found so far, and how far a nearer one can be.
  struct NearestSoFar
  {
    std::int32_t Best = kNone;
    Point2 BestPoint;
    double Reach = std::numeric_limits<double>::infinity();
    void Offer(std::int32_t q, const Point2& pq, const Point2& pa);
  };
  void OfferStripNear(std::int32_t s,
    std::int32_t a,
    const Point2& pa,
    NearestSoFar& nearest) const;
  Entry SearchAndRecord(std::int32_t cur);
  void SearchNext(std::int32_t cur);
  void StartSearch(std::int32_t cur);
  int DummiesInE1(std::int32_t* dummies); ///< they go to dummies; returns how many
  void FindFirstCandidate(const std::int32_t* dummies,
    int dummyCount,
    std::int32_t& lo,
    std::int32_t& hi);
  bool StepCursors(); ///< one step of every cursor (until P is found); whether one visited
  void BoundByDummies(const std::int32_t* dummies, int dummyCount);
  void ScanRemainingStrips(std::int32_t lo, std::int32_t hi);
  void ConsiderDummies(const std::int32_t* dummies, int dummyCount);
  bool DummyOutsideRange(std::int32_t dummy) const;
  bool StripMeetsRangeRight(std::int32_t s) const { return this->StripXLo[s] <= this->Range.XHi; }
  bool StripMeetsRangeLeft(std::int32_t s) const { return this->StripXHi[s] >= this->Range.XLo; }
  struct Cursor
  {
    std::int32_t Strip;
    std::int32_t Begin, End; ///< the strip's positions
    std::int32_t Up, Down;   ///< next positions to visit above and below A's ordinate
    double YLo, YHi;         ///< ordinates of the range within the strip's abscissae
    std::uint32_t Version;   ///< RangeVersion the limits were computed for
  };
  Cursor MakeCursor(std::int32_t strip);
  bool StripMissesBound(std::int32_t strip) const;
  bool StripSegmentOutsideE1(std::int32_t strip) const;
  void LimitCursor(Cursor& c);
  void LimitToHorizontalChord(Cursor& c);
  bool StepCursor(Cursor& c);
  void Drain(Cursor& c)
  {
    while (this->StepCursor(c))
    {
    }
  }
  static bool IsExhausted(const Cursor& c) { return c.Up >= c.End && c.Down < c.Begin; }
  static void Exhaust(Cursor& c)
  {
    c.Up = c.End;
    c.Down = c.Begin - 1;
  }
  void Visit(const StripPoint& point);
  /// A visited centroid q (at pq) against the circle: the fast path, on the points at hand.
  void ConsiderPoint(std::int32_t q, const Point2& pq);
  /// A dummy against the circle (exactly, on offsets from A): the last tests of a search.
  void ConsiderDummy(std::int32_t q);
  /// q as the search's potential neighbour P (inside > 0: in the circle through A, Cur and P, or
  /// the first site found), a tie with it (0), or not (< 0); pq: q's point, when a centroid.
  void TakeIfInside(std::int32_t q, int inside, const Point2* pq);
  std::int32_t LowerBound(std::int32_t begin, std::int32_t end, double y) const;
  static int OrientDummyPoint(std::int32_t dummy, const Point2& a, const Point2& q);
  /// orient2d(A, Cur, q): E1, the half-plane searched, is where it is negative.
  int SideOfCur(const Point2& q) const
  {
    return this->Cur >= 0 ? orient2d_fast(this->PA, this->PCur, q)
                          : OrientDummyPoint(this->Cur, this->PA, q);
  }
  bool HasBound() const { return this->Bound.R < std::numeric_limits<double>::infinity(); }
  void UpdateBox();
  void AddRecord(std::int32_t c, std::int32_t in, std::int32_t out, std::int32_t vertex);
  struct CircleSites;
  CircleSites SitesOf(const std::vector<std::int32_t>& circle) const;
  Point2 FaceCentre(const CircleSites& sites) const;
  Point2 WhereBisectorMeetsSide(const Point2& p, const Point2& q, const CircleSites& sites) const;
  void ListCircle(std::int32_t cur);
  /// The vertex's entry for each centroid on its circle but A.
  void RecordVertexForOthers(std::int32_t vertex);
  void RecordHalfNeighbours();

  // Sites relative to A.
  void ApproxOffset(std::int32_t s, double& ox, double& oy) const;
  Offset2 ExactOffset(std::int32_t s) const;
  int Orient(std::int32_t s1, std::int32_t s2) const; // orient2d(A, s1, s2)
  int InCircle(std::int32_t q) const;                 // q inside the circle (A, Cur, P)?

  double XMin, XMax, YMin, YMax;
  std::vector<double> Xs, Ys;
  std::vector<std::int32_t> IdOf;
  std::int32_t M;

  // Bucket index: strips of about sqrt(M) consecutive x-sorted centroids (never splitting a set
  // of equal abscissae: a column of points is one strip), each sorted by y (CutStrips).
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
  this->CutStrips();
  this->SortStrips();
  this->PlaceInNeighbourStrips();
}

// About sqrt(M) strips of sqrt(M) centroids: a circle spanning a few point spacings then meets a
// couple of strips and a few points in each.
void Sweep::CutStrips()
{
  const std::int32_t stripSize =
    std::max<std::int32_t>(4, static_cast<std::int32_t>(std::sqrt(double(this->M))));
  this->StripBegin.assign(1, 0);
  while (this->StripBegin.back() < this->M)
  {
    std::int32_t end = std::min(this->M, this->StripBegin.back() + stripSize);
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
}

// Each strip's points by y (then x-sorted index), its bounds, and each point's place in it.
void Sweep::SortStrips()
{
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
}

// Merges each pair of adjacent strips once (both sorted by y) to place every point in its
// neighbours: PositionLeft and PositionRight.
void Sweep::PlaceInNeighbourStrips()
{
  this->PositionLeft.assign(this->M, 0);
  this->PositionRight.assign(this->M, 0);
  for (std::int32_t s = 0; s + 1 < this->StripCount; ++s)
  {
    const std::int32_t left = this->StripBegin[s], middle = this->StripBegin[s + 1];
    const std::int32_t right = this->StripBegin[s + 2];
    this->PlaceIn(left, middle, middle, right, this->PositionRight);
    this->PlaceIn(middle, right, left, middle, this->PositionLeft);
  }
}

// For each point of strip positions [from, fromEnd), the first position of [to, toEnd) whose
// ordinate is not smaller, into position (by x-sorted index). Both ranges sorted by y.
void Sweep::PlaceIn(std::int32_t from,
  std::int32_t fromEnd,
  std::int32_t to,
  std::int32_t toEnd,
  std::vector<std::int32_t>& position) const
{
  std::int32_t j = to;
  for (std::int32_t i = from; i < fromEnd; ++i)
  {
    while (j < toEnd && this->Strip[j].Y < this->Strip[i].Y)
    {
      ++j;
    }
    position[this->Strip[i].S] = j;
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

/// The first centroid nearest to v (a brute-force scan: once per sweep); unique: no other is as
/// near.
std::int32_t Sweep::NearestToCorner(const Point2& v, bool& unique) const
{
  std::int32_t nearest = 0;
  unique = true;
  for (std::int32_t s = 1; s < this->M; ++s)
  {
    const int c = compare_distance_fast(
      v, Point2{ this->Xs[s], this->Ys[s] }, Point2{ this->Xs[nearest], this->Ys[nearest] });
    if (c < 0)
    {
      nearest = s;
      unique = true;
    }
    else if (c == 0)
    {
      unique = false;
    }
  }
  return nearest;
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
  bool unique = true;
  const std::int32_t first = this->NearestToCorner(v0, unique);
  if (unique)
  {
    this->Vertices.push_back(v0);
    this->AddRecord(first, kBottom, kLeft, 0);
  }
  this->ProcessCentroid(first);
  for (std::int32_t s = 0; s < this->M; ++s)
  {
    if (s % 64 == 0)
    {
      ReportOrStop(progress, static_cast<double>(s) / this->M);
    }
    if (s != first)
    {
      this->ProcessCentroid(s);
    }
  }
}

// Any nearest centroid N shares a side of positive length with A: the midpoint of AN is nearer to
// A and N than to any other centroid, and inside the (convex) window.
std::int32_t Sweep::NearestCentroid(std::int32_t a) const
{
  NearestSoFar nearest;
  const Point2 pa{ this->Xs[a], this->Ys[a] };
  const auto scan = [&](std::int32_t s) { this->OfferStripNear(s, a, pa, nearest); };
  const std::int32_t s0 = this->StripOf[a];
  scan(s0);
  ScanOutward(
    s0,
    s0,
    this->StripCount,
    [&](std::int32_t s) { return this->StripXLo[s] - pa.x <= nearest.Reach; },
    [&](std::int32_t s) { return pa.x - this->StripXHi[s] <= nearest.Reach; },
    scan);
  return nearest.Best;
}

void Sweep::NearestSoFar::Offer(std::int32_t q, const Point2& pq, const Point2& pa)
{
  if (this->Best != kNone && compare_distance_fast(pa, pq, this->BestPoint) >= 0)
  {
    return;
  }
  this->Best = q;
  this->BestPoint = pq;
  const double dx = pq.x - pa.x, dy = pq.y - pa.y;
  // (hypot where the squares underflow or overflow: points 1e-200 apart had a reach of 1e-300,
  // which missed their nearest centroid, and the sweep failed with a logic_error)
  const double squares = dx * dx + dy * dy;
  const double distance =
    squares > 1e-280 && squares < 1e280 ? std::sqrt(squares) : std::hypot(dx, dy);
  this->Reach = distance * (1.0 + 1e-9) + 1e-300;
}

// Offers the points of strip s within the reach of a's ordinate, outward from it, alternately up
// and down (the reach shrinking as nearer ones are found), those within reach in abscissa too.
void Sweep::OfferStripNear(std::int32_t s,
  std::int32_t a,
  const Point2& pa,
  NearestSoFar& nearest) const
{
  const std::int32_t begin = this->StripBegin[s];
  const std::int32_t end = this->StripBegin[s + 1];
  const auto offer = [&](const StripPoint& point)
  {
    if (point.S != a && std::fabs(point.X - pa.x) <= nearest.Reach)
    {
      nearest.Offer(point.S, Point2{ point.X, point.Y }, pa);
    }
  };
  std::int32_t up = this->LowerBound(begin, end, pa.y);
  std::int32_t down = up - 1;
  while (up < end || down >= begin)
  {
    if (up < end)
    {
      if (this->Strip[up].Y - pa.y <= nearest.Reach)
      {
        offer(this->Strip[up++]);
      }
      else
      {
        up = end;
      }
    }
    if (down >= begin)
    {
      if (pa.y - this->Strip[down].Y <= nearest.Reach)
      {
        offer(this->Strip[down--]);
      }
      else
      {
        down = begin - 1;
      }
    }
  }
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

void Sweep::ConsiderDummy(std::int32_t q)
{
  this->TakeIfInside(q, this->P == kNone ? 1 : this->InCircle(q), nullptr);
}

void Sweep::ConsiderPoint(std::int32_t q, const Point2& pq)
{
  // P is a centroid here (the dummies come last), so PP is its point; PCur is Cur's when Cur is
  // a centroid.
  const int inside = this->P == kNone ? 1
    : this->Cur >= 0                  ? incircle_fast(this->PA, this->PP, this->PCur, pq)
                                      : this->InCircle(q);
  this->TakeIfInside(q, inside, &pq);
}

void Sweep::TakeIfInside(std::int32_t q, int inside, const Point2* pq)
{
  if (inside < 0)
  {
    return;
  }
  if (this->P != kNone)
  {
    ++this->Count->InCircle; // (the first site found is no test)
  }
  if (inside == 0)
  {
    // Fig. 5: on the circle, a tie. Any of the ties gives the same circle, and they are sorted
    // round it once the search ends (the paper kept the less clockwise as P: no need).
    this->Ties.push_back(q);
    return;
  }
  this->P = q;
  if (pq)
  {
    this->PP = *pq;
  }
  this->Ties.clear();
  this->UpdateBox();
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
  const int side = this->SideOfCur(pq);
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
  if (this->StripMissesBound(strip) || this->StripSegmentOutsideE1(strip))
  {
    Exhaust(c);
    return c;
  }
  c.Up = this->StripStart(strip);
  c.Down = c.Up - 1;
  return c;
}

// A strip whose bounding box misses the bounding disk holds no candidate (generous slack: this
// only prunes).
bool Sweep::StripMissesBound(std::int32_t strip) const
{
  const Disk& d = this->Bound;
  if (!this->HasBound())
  {
    return false;
  }
  const double xlo = this->StripXLo[strip], xhi = this->StripXHi[strip];
  const double ylo = this->StripYLo[strip], yhi = this->StripYHi[strip];
  const double dx = DistanceOutside(d.X, xlo, xhi);
  const double dy = DistanceOutside(d.Y, ylo, yhi);
  return dx * dx + dy * dy > d.R * d.R * (1.0 + 1e-9);
}

// A strip whose points all lie on one vertical or horizontal segment (collinear input, a lattice
// column) is skipped when the segment is in the closed side E2 of A -> Cur: none of its points can
// be in E1.
bool Sweep::StripSegmentOutsideE1(std::int32_t strip) const
{
  const double xlo = this->StripXLo[strip], xhi = this->StripXHi[strip];
  const double ylo = this->StripYLo[strip], yhi = this->StripYHi[strip];
  if (xlo != xhi && ylo != yhi)
  {
    return false;
  }
  const Point2 ends[2] = { { xlo, ylo }, { xhi, yhi } };
  for (const Point2& e : ends)
  {
    const int side = this->SideOfCur(e);
    if (side < 0)
    {
      return false;
    }
  }
  return true;
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
  if (!this->HasBound())
  {
    return;
  }
  if (this->StripYLo[c.Strip] == this->StripYHi[c.Strip])
  {
    this->LimitToHorizontalChord(c);
    return;
  }
  const double xlo = this->StripXLo[c.Strip], xhi = this->StripXHi[c.Strip];
  const double dx = DistanceOutside(d.X, xlo, xhi) * (1.0 - 1e-12);
  if (dx > d.R)
  {
    Exhaust(c);
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

// All the strip's points on one horizontal line (sorted by x there): keep the chord of the
// bounding disk along that line.
void Sweep::LimitToHorizontalChord(Cursor& c)
{
  const Disk& d = this->Bound;
  const double dy = std::fabs(this->StripYLo[c.Strip] - d.Y) * (1.0 - 1e-12);
  if (dy > d.R)
  {
    Exhaust(c);
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
}

bool Sweep::StepCursor(Cursor& c)
{
  // One point up and one point down from A's ordinate, while inside the (shrinking) range. (An
  // exhausted cursor first: limiting one cost two binary searches for nothing.)
  if (IsExhausted(c))
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
  this->StartSearch(cur);
  // The dummies in E1 (there is always one). The paper starts from one of them as the first
  // potential neighbour; here their circles first only bound the range (a dummy's circle is
  // large for a centroid far from the border), the centroids are searched, and the dummies are
  // tested last, exactly like any point. The result is the same: the sites on the smallest circle
  // (P and its ties, sorted round it afterwards), whatever the order of the tests.
  std::int32_t dummies[4];
  const int dummyCount = this->DummiesInE1(dummies);
  std::int32_t lo = this->StripOf[this->A], hi = lo; // the strips begun
  this->FindFirstCandidate(dummies, dummyCount, lo, hi);
  this->ScanRemainingStrips(lo, hi);
  this->ConsiderDummies(dummies, dummyCount);
}

void Sweep::StartSearch(std::int32_t cur)
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
}

int Sweep::DummiesInE1(std::int32_t* dummies)
{
  int count = 0;
  for (const std::int32_t d : { kLeft, kBottom, kRight, kTop })
  {
    if (d == this->Cur)
    {
      continue;
    }
    ++this->Count->Consulted;
    if (this->Orient(this->Cur, d) < 0)
    {
      ++this->Count->PassedTests;
      dummies[count++] = d;
    }
  }
  if (count == 0)
  {
    throw std::logic_error("Brassel-Reif sweep: no dummy point in the clockwise half-plane");
  }
  return count;
}

// Until a first centroid of E1 is found there is no range: step outward in A's strip, and widen
// to the neighbouring strips round by round (A's strip may hold none: a lattice column when Cur is
// straight above A). After two rounds the dummies' circles bound the range, so that a centroid
// with no point of E1 nearby does not scan everything. [lo, hi]: the strips begun (A's on entry).
void Sweep::FindFirstCandidate(const std::int32_t* dummies,
  int dummyCount,
  std::int32_t& lo,
  std::int32_t& hi)
{
  this->Cursors.assign(1, this->MakeCursor(lo));
  bool bounded = false;
  for (int round = 1;; ++round) // (until a centroid of E1 is found, or none can be)
  {
    const bool visited = this->StepCursors();
    if (this->P != kNone)
    {
      break;
    }
    bool widened = false;
    if (hi + 1 < this->StripCount && this->StripMeetsRangeRight(hi + 1))
    {
      this->Cursors.push_back(this->MakeCursor(++hi));
      widened = true;
    }
    if (lo > 0 && this->StripMeetsRangeLeft(lo - 1))
    {
      this->Cursors.push_back(this->MakeCursor(--lo));
      widened = true;
    }
    const bool stalled = !visited && !widened;
    if (!bounded && (round >= 2 || stalled))
    {
      this->BoundByDummies(dummies, dummyCount);
      bounded = true;
    }
    else if (stalled)
    {
      break; // no centroid of E1 within the dummies' circles
    }
  }
}

bool Sweep::StepCursors()
{
  bool visited = false;
  for (std::size_t k = 0; k < this->Cursors.size() && this->P == kNone;)
  {
    Cursor& c = this->Cursors[k];
    visited = this->StepCursor(c) || visited;
    if (IsExhausted(c))
    {
      c = this->Cursors.back(); // drop it
      this->Cursors.pop_back();
    }
    else
    {
      ++k;
    }
  }
  return visited;
}

// The range narrowed to the dummies' circles: each dummy is P just long enough for UpdateBox,
// and P is none again after, so that the search goes on for a centroid.
void Sweep::BoundByDummies(const std::int32_t* dummies, int dummyCount)
{
  for (int k = 0; k < dummyCount; ++k)
  {
    this->P = dummies[k];
    this->UpdateBox();
  }
  this->P = kNone;
}

// Finishes the strips begun, then goes outward, alternately right and left, while the strips meet
// the abscissa range (with a potential neighbour, the range of its circle; without one, that of
// the dummies' circles).
void Sweep::ScanRemainingStrips(std::int32_t lo, std::int32_t hi)
{
  for (Cursor& c : this->Cursors)
  {
    this->Drain(c);
  }
  ScanOutward(
    lo,
    hi,
    this->StripCount,
    [this](std::int32_t s) { return this->StripMeetsRangeRight(s); },
    [this](std::int32_t s) { return this->StripMeetsRangeLeft(s); },
    [this](std::int32_t s)
    {
      Cursor c = this->MakeCursor(s);
      this->Drain(c);
    });
}

void Sweep::ConsiderDummies(const std::int32_t* dummies, int dummyCount)
{
  for (int k = 0; k < dummyCount; ++k)
  {
    if (this->P != kNone && this->DummyOutsideRange(dummies[k]))
    {
      continue; // outside the circle: no exact test
    }
    this->ConsiderDummy(dummies[k]);
  }
}

// Whether the dummy's rounded position (within an ulp or two of the exact reflection) lies beyond
// the range by more than its rounding: then it is outside the circle.
bool Sweep::DummyOutsideRange(std::int32_t dummy) const
{
  double ox, oy;
  this->ApproxOffset(dummy, ox, oy);
  const double x = this->PA.x + ox, y = this->PA.y + oy;
  const double margin = 4.0 * kUnit * (std::fabs(x) + std::fabs(y) + std::fabs(ox) + std::fabs(oy));
  return x < this->Range.XLo - margin || x > this->Range.XHi + margin ||
    y < this->Range.YLo - margin || y > this->Range.YHi + margin;
}

// What FaceCentre needs of a circle's sites: the window sides among them (dummies), and the
// first three centroids by ComesFirst.
struct Sweep::CircleSites
{
  bool Vertical = false, Horizontal = false;
  double XSide = 0.0, YSide = 0.0;
  std::int32_t First[3] = { kNone, kNone, kNone };
};

Sweep::CircleSites Sweep::SitesOf(const std::vector<std::int32_t>& circle) const
{
  CircleSites sites;
  for (const std::int32_t s : circle)
  {
    if (s == kLeft || s == kRight)
    {
      sites.Vertical = true;
      sites.XSide = s == kLeft ? this->XMin : this->XMax;
    }
    else if (s == kBottom || s == kTop)
    {
      sites.Horizontal = true;
      sites.YSide = s == kBottom ? this->YMin : this->YMax;
    }
    else
    {
      std::int32_t c = s; // insertion into First
      for (std::int32_t& slot : sites.First)
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
  return sites;
}

Point2 Sweep::FaceCentre(const CircleSites& sites) const
{
  if (sites.Vertical && sites.Horizontal)
  {
    return { sites.XSide, sites.YSide }; // a window corner
  }
  // Not a corner: at least two centroids besides the one side, or three without a side.
  const Point2 p{ this->Xs[sites.First[0]], this->Ys[sites.First[0]] };
  const Point2 q{ this->Xs[sites.First[1]], this->Ys[sites.First[1]] };
  if (sites.Vertical || sites.Horizontal)
  {
    return this->WhereBisectorMeetsSide(p, q, sites);
  }
  // From the first three points by ComesFirst, as tiles.cpp computes it (circumcentre.h), so
  // that interior vertices get the same bits from both engines.
  return CircumcentreOf(p, q, Point2{ this->Xs[sites.First[2]], this->Ys[sites.First[2]] });
}

// Where the bisector of centroids p and q crosses the one window side among the sites (a circle
// through a side's dummy holds at least two centroids besides it).
Point2 Sweep::WhereBisectorMeetsSide(const Point2& p,
  const Point2& q,
  const CircleSites& sites) const
{
  if (sites.Vertical)
  {
    const double y = 0.5 * (p.y + q.y) +
      (q.x - p.x) * ((sites.XSide - p.x) + (sites.XSide - q.x)) / (2.0 * (p.y - q.y));
    return { sites.XSide, std::min(std::max(y, this->YMin), this->YMax) };
  }
  const double x = 0.5 * (p.x + q.x) +
    (q.y - p.y) * ((sites.YSide - p.y) + (sites.YSide - q.y)) / (2.0 * (p.x - q.x));
  return { std::min(std::max(x, this->XMin), this->XMax), sites.YSide };
}

Sweep::Entry Sweep::SearchAndRecord(std::int32_t cur)
{
  this->SearchNext(cur);
  this->ListCircle(cur);
  const std::int32_t vertex = static_cast<std::int32_t>(this->Vertices.size());
  const CircleSites sites = this->SitesOf(this->Circle);
  this->Vertices.push_back(this->FaceCentre(sites));
  this->RecordVertexForOthers(vertex);
  if (this->Circle.size() >= 4)
  {
    ++this->DegenerateVertices;
    if (!sites.Vertical && !sites.Horizontal) // (no window side on the circle)
    {
      this->RecordHalfNeighbours();
    }
  }
  return Entry{ cur, this->Circle[1], vertex, -1 };
}

// The sites on the circle in E1, clockwise around A from Cur; then the circle anticlockwise into
// Circle: A, the most clockwise (A's next neighbour), ..., the least clockwise, Cur.
void Sweep::ListCircle(std::int32_t cur)
{
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
}

// The vertex's entry (in, out) for each centroid on the circle but A.
void Sweep::RecordVertexForOthers(std::int32_t vertex)
{
  const std::size_t m = this->Circle.size();
  for (std::size_t i = 1; i < m; ++i)
  {
    const std::int32_t c = this->Circle[i];
    if (c < 0)
    {
      continue; // a window side
    }
    if (this->Processed[c])
    {
      // That centroid's own search would have found this vertex and recorded it for A.
      throw std::logic_error("Brassel-Reif sweep: inconsistent vertex (point " +
        std::to_string(this->IdOf[c]) + " already completed)");
    }
    this->AddRecord(c, this->Circle[i - 1], this->Circle[(i + 1) % m], vertex);
  }
}

// Sites not adjacent around a circle of four or more centroids meet at its vertex only:
// half-neighbours.
void Sweep::RecordHalfNeighbours()
{
  const std::size_t m = this->Circle.size();
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

void Sweep::ProcessCentroid(std::int32_t a)
{
  this->A = a;
  this->PA = Point2{ this->Xs[a], this->Ys[a] };
  this->Count = &this->Records[a].Counts;
  this->TakeKnownEntries(a);
  this->SeedStripStarts(a);
  this->WalkClockwise(a);
  this->StoreTile(a);
  this->Processed[a] = 1;
}

// The entries other centroids recorded for a, into Known; the record is dropped and its entries
// recycled.
void Sweep::TakeKnownEntries(std::int32_t a)
{
  this->Known.clear();
  for (std::int32_t e = this->Head[a]; e >= 0;)
  {
    const std::int32_t next = this->Pool[e].Next;
    this->Known.push_back(this->Pool[e]);
    this->Pool[e].Next = this->FreeEntry;
    this->FreeEntry = e;
    e = next;
  }
  this->Head[a] = -1;
}

// Where a's ordinate falls in its strip and its two neighbours, known from the index.
void Sweep::SeedStripStarts(std::int32_t a)
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

// a's vertices clockwise into Cycle, each (in, out, vertex): from its known entries where they go
// on, by searches where they do not, until the walk comes back to its first vertex. Without
// known entries the walk starts from the nearest centroid, a neighbour (from the left side when a
// is the only centroid).
void Sweep::WalkClockwise(std::int32_t a)
{
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
    const Entry* known = this->KnownEntryFrom(cur);
    if (known != nullptr && known->Vertex == firstVertex)
    {
      break;
    }
    const Entry next = known != nullptr ? *known : this->SearchAndRecord(cur);
    if (firstVertex < 0) // (only after a search: known entries set firstVertex at the start)
    {
      firstVertex = next.Vertex;
      this->Known.push_back(next); // so that the walk recognises where it closes
    }
    this->Cycle.push_back(next);
    cur = next.Out;
    if (this->Cycle.size() > limit)
    {
      throw std::logic_error("Brassel-Reif sweep: the polygon of point " +
        std::to_string(this->IdOf[a]) + " does not close");
    }
  }
}

const Sweep::Entry* Sweep::KnownEntryFrom(std::int32_t in) const
{
  for (const Entry& e : this->Known)
  {
    if (e.In == in)
    {
      return &e;
    }
  }
  return nullptr;
}

// The walk went clockwise: stored anticlockwise. Vertex k is followed (anticlockwise) by the side
// shared with the `in` neighbour of its entry.
void Sweep::StoreTile(std::int32_t a)
{
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

namespace
{

/// The checks ComputeThiessenSweep makes before it looks at a point's place.
void CheckSweepable(const Window& window, const std::vector<Point2>& points)
{
  const std::string notRectangle = WhyNotAnAxisAlignedRectangle(window);
  if (!notRectangle.empty())
  {
    throw InputError(
      "the Brassel-Reif sweep needs an axis-aligned rectangular window: " + notRectangle);
  }
  CheckSidesAreDoubles(window);
  if (points.size() >= std::size_t(std::numeric_limits<std::int32_t>::max() / 4))
  {
    throw InputError(
      "too many points for the Brassel-Reif sweep: " + std::to_string(points.size()));
  }
  CheckPointsAreFinite(points);
}

/// The window's bounds scaled by 2^scale, which must leave room for the reflections.
Box2 ScaledBounds(const Box2& bounds, int scale)
{
  const Box2 scaled{ std::ldexp(bounds.XMin, scale),
    std::ldexp(bounds.XMax, scale),
    std::ldexp(bounds.YMin, scale),
    std::ldexp(bounds.YMax, scale) };
  // (overflowing, the dummy points left the sweep without one, a logic_error)
  if (!(scaled.LargestMagnitude() < ReflectionReach))
  {
    throw InputError("the Brassel-Reif sweep reflects the points across the window's sides, "
                     "which overflows for a window reaching " +
      NumberText(bounds.LargestMagnitude()) +
      " (beyond some 4e307) that cannot be scaled down exactly with its points (numbers below "
      "some 1e-308 among them): scale them down (the filter vtkDirichletTessellation does)");
  }
  return scaled;
}

/// An accepted point, scaled, with its id; the sweep takes them by (x, y, id).
struct KeyedPoint
{
  double X, Y;
  std::int32_t Id;
};

/// The points strictly inside the window (its own test), scaled by 2^scale; the others' ids go to
/// rejected, ascending.
std::vector<KeyedPoint> KeepInside(const Box2& bounds,
  int scale,
  const std::vector<Point2>& points,
  std::vector<std::int32_t>& rejected)
{
  std::vector<KeyedPoint> keyed;
  keyed.reserve(points.size());
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
      rejected.push_back(static_cast<std::int32_t>(i));
    }
  }
  return keyed;
}

/// Sorts by (x, y, id): buckets by abscissa over [xmin, xmax] (a monotone function of x), then
/// each bucket sorted.
void SortByAbscissa(std::vector<KeyedPoint>& keyed, double xmin, double xmax)
{
  const auto less = [](const KeyedPoint& p, const KeyedPoint& q)
  { return p.X < q.X || (p.X == q.X && (p.Y < q.Y || (p.Y == q.Y && p.Id < q.Id))); };
  const std::size_t buckets =
    std::max<std::size_t>(1, std::min<std::size_t>(4096, keyed.size() / 64));
  const double perUnit = double(buckets) / (xmax - xmin);
  const auto bucketOf = [&](double x)
  {
    const double b = std::floor((x - xmin) * perUnit);
    return b <= 0.0 ? std::size_t(0) : std::min(buckets - 1, std::size_t(b));
  };
  std::vector<std::size_t> start(buckets + 1, 0);
  for (const KeyedPoint& k : keyed)
  {
    ++start[bucketOf(k.X) + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b)
  {
    start[b + 1] += start[b];
  }
  std::vector<KeyedPoint> sorted(keyed.size());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const KeyedPoint& k : keyed)
  {
    sorted[fill[bucketOf(k.X)]++] = k;
  }
  for (std::size_t b = 0; b < buckets; ++b)
  {
    std::sort(sorted.begin() + start[b], sorted.begin() + start[b + 1], less);
  }
  keyed.swap(sorted);
}

/// The sweep's centroids: the sorted points without repeats (each repeat's (id, kept id) goes to
/// duplicates, ascending).
struct Centroids
{
  std::vector<double> Xs, Ys;
  std::vector<std::int32_t> Ids;
};

Centroids WithoutRepeats(const std::vector<KeyedPoint>& keyed,
  std::vector<std::pair<std::int32_t, std::int32_t>>& duplicates)
{
  Centroids c;
  c.Xs.reserve(keyed.size());
  c.Ys.reserve(keyed.size());
  c.Ids.reserve(keyed.size());
  for (const KeyedPoint& k : keyed)
  {
    if (!c.Ids.empty() && c.Xs.back() == k.X && c.Ys.back() == k.Y)
    {
      duplicates.emplace_back(k.Id, c.Ids.back());
      continue;
    }
    c.Xs.push_back(k.X);
    c.Ys.push_back(k.Y);
    c.Ids.push_back(k.Id);
  }
  std::sort(duplicates.begin(), duplicates.end());
  return c;
}

/// The half-neighbours as (i, j) point ids, i < j, sorted.
std::vector<std::pair<std::int32_t, std::int32_t>> HalfNeighbourIds(const Sweep& sweep)
{
  const std::vector<std::int32_t>& idOf = sweep.Ids();
  std::vector<std::pair<std::int32_t, std::int32_t>> half;
  half.reserve(sweep.Kind1.size());
  for (const auto& pair : sweep.Kind1)
  {
    const std::int32_t i = idOf[pair.first], j = idOf[pair.second];
    half.emplace_back(std::min(i, j), std::max(i, j));
  }
  std::sort(half.begin(), half.end());
  return half;
}

/// Gathers the sweep's tiles, in ascending id, into the result: its records are in x-sorted
/// order, unrelated to the ids, so each is prefetched ahead and appended sequentially.
class TileGatherer
{
public:
  TileGatherer(const Sweep& sweep, std::size_t pointCount, int scale)
    : S(sweep)
    , Scale(scale)
    , SortedOf(pointCount, -1)
    , Half(HalfNeighbourIds(sweep))
  {
    const std::vector<std::int32_t>& idOf = sweep.Ids();
    for (std::size_t s = 0; s < idOf.size(); ++s)
    {
      this->SortedOf[idOf[s]] = static_cast<std::int32_t>(s);
    }
    this->AcceptedIds.reserve(idOf.size());
    for (std::size_t id = 0; id < pointCount; ++id)
    {
      if (this->SortedOf[id] >= 0)
      {
        this->AcceptedIds.push_back(static_cast<std::int32_t>(id));
      }
    }
  }

  void Into(ThiessenSweepResult& result)
  {
    this->Reserve(result);
    result.Tiles.Offsets.push_back(0);
    constexpr std::size_t ahead = 4;
    const std::size_t accepted = this->AcceptedIds.size();
    const std::int32_t* vertexIds = this->S.PackedVertexIds.data();
    for (std::size_t r = 0; r < accepted; ++r)
    {
      // Three stages of prefetching: a tile's record, then its vertex ids and neighbours, then its
      // vertices' coordinates. (Here, not in a function of their own: GCC found such a function
      // free of side effects, and removed its calls.)
      if (r + 3 * ahead < accepted)
      {
        __builtin_prefetch(&this->RecordOf(this->AcceptedIds[r + 3 * ahead]));
      }
      if (r + 2 * ahead < accepted)
      {
        const Sweep::TileRecord& later = this->RecordOf(this->AcceptedIds[r + 2 * ahead]);
        __builtin_prefetch(vertexIds + later.Start);
        __builtin_prefetch(this->S.PackedNeighbors.data() + later.Start);
      }
      if (r + ahead < accepted)
      {
        const Sweep::TileRecord& later = this->RecordOf(this->AcceptedIds[r + ahead]);
        for (std::int32_t k = 0; k < later.Size; ++k)
        {
          __builtin_prefetch(&this->S.Vertices[vertexIds[later.Start + k]]);
        }
      }
      const std::int32_t id = this->AcceptedIds[r];
      const Sweep::TileRecord& record = this->RecordOf(id);
      this->AppendTile(id, record, result);
      this->AppendContiguities(id, record, result.Contiguities);
    }
    NumberCornerVertices(this->S.Vertices.size(), this->Merged, result.CornerVertexIds);
  }

private:
  const Sweep::TileRecord& RecordOf(std::int32_t id) const
  {
    return this->S.Records[this->SortedOf[id]];
  }

  void Reserve(ThiessenSweepResult& result) const
  {
    const std::size_t accepted = this->AcceptedIds.size();
    TileSet& tiles = result.Tiles;
    tiles.PointIds.reserve(accepted);
    tiles.Offsets.reserve(accepted + 1);
    tiles.Vertices.reserve(this->S.PackedVertexIds.size());
    tiles.Areas.reserve(accepted);
    tiles.NeighborCounts.reserve(accepted);
    result.Counts.reserve(accepted);
    result.Contiguities.Pairs.reserve(this->S.PackedNeighbors.size() + 2 * this->Half.size());
    result.Contiguities.Kinds.reserve(this->S.PackedNeighbors.size() / 2 + this->Half.size());
    result.CornerVertexIds.reserve(this->S.PackedVertexIds.size());
  }

  void AppendTile(std::int32_t id, const Sweep::TileRecord& record, ThiessenSweepResult& result)
  {
    TileSet& tiles = result.Tiles;
    tiles.PointIds.push_back(id);
    this->Polygon.clear();
    this->Corners.clear();
    for (std::int32_t k = 0; k < record.Size; ++k)
    {
      const std::int32_t vertex = this->S.PackedVertexIds[record.Start + k];
      const Point2& v = this->S.Vertices[vertex];
      this->Polygon.push_back(this->Scale == 0
          ? v
          : Point2{ std::ldexp(v.x, -this->Scale), std::ldexp(v.y, -this->Scale) });
      this->Corners.push_back(vertex);
    }
    // Distinct Thiessen vertices can round to one point (the circumcentres of nearly co-circular
    // points, a window crossing within rounding of a corner): the polygon lists it once, as the
    // Green-Sibson engine's does, and the vertices are made one. Its area and NeighborCount (the
    // exact sides) stay as they are.
    if (HasRepeatedVertex(this->Polygon))
    {
      DropRepeatedVertices(this->Polygon, this->Corners, &this->Merged);
    }
    tiles.Vertices.insert(tiles.Vertices.end(), this->Polygon.begin(), this->Polygon.end());
    result.CornerVertexIds.insert(
      result.CornerVertexIds.end(), this->Corners.begin(), this->Corners.end());
    tiles.Offsets.push_back(static_cast<std::int64_t>(tiles.Vertices.size()));
    tiles.Areas.push_back(
      this->Scale == 0 ? record.Area : std::ldexp(record.Area, -2 * this->Scale));
    tiles.NeighborCounts.push_back(record.Size);
    result.Counts.push_back(record.Counts);
  }

  // The tile's neighbours and half-neighbours with larger ids, ascending.
  void AppendContiguities(std::int32_t id, const Sweep::TileRecord& record, ContiguityGraph& graph)
  {
    this->Group.clear();
    for (std::int32_t k = 0; k < record.Size; ++k)
    {
      const std::int32_t n = this->S.PackedNeighbors[record.Start + k];
      if (n > id)
      {
        this->Group.emplace_back(n, 0);
      }
    }
    while (this->NextHalf < this->Half.size() && this->Half[this->NextHalf].first == id)
    {
      this->Group.emplace_back(this->Half[this->NextHalf++].second, 1);
    }
    std::sort(this->Group.begin(), this->Group.end());
    for (const auto& g : this->Group)
    {
      graph.Pairs.push_back(id);
      graph.Pairs.push_back(g.first);
      graph.Kinds.push_back(g.second);
    }
  }

  const Sweep& S;
  const int Scale;
  std::vector<std::int32_t> SortedOf;    // per point id: its x-sorted index, -1 when not accepted
  std::vector<std::int32_t> AcceptedIds; // ascending
  const std::vector<std::pair<std::int32_t, std::int32_t>> Half; // HalfNeighbourIds
  std::size_t NextHalf = 0;
  std::vector<Point2> Polygon;                               // a tile's vertices (scratch)
  std::vector<std::int32_t> Corners;                         // and the Thiessen vertex of each
  std::vector<std::pair<std::int32_t, std::int32_t>> Merged; // vertices that round to one point
  std::vector<std::pair<std::int32_t, std::uint8_t>> Group;  // a tile's contiguities (scratch)
};

} // namespace

ThiessenSweepResult ComputeThiessenSweep(const Window& window,
  const std::vector<Point2>& points,
  const std::function<bool(double)>& progress)
{
  CheckSweepable(window, points);
  const Box2 bounds = window.Bounds();
  const int scale = SweepScale(bounds, points);
  const Box2 scaled = ScaledBounds(bounds, scale);
  ThiessenSweepResult result;
  std::vector<KeyedPoint> keyed = KeepInside(bounds, scale, points, result.RejectedIds);
  SortByAbscissa(keyed, scaled.XMin, scaled.XMax); // (the keys are scaled: so is their range)
  Centroids centroids = WithoutRepeats(keyed, result.Duplicates);
  keyed = std::vector<KeyedPoint>();

  Sweep sweep(scaled.XMin,
    scaled.XMax,
    scaled.YMin,
    scaled.YMax,
    std::move(centroids.Xs),
    std::move(centroids.Ys),
    std::move(centroids.Ids));
  sweep.Run(progress);
  result.VertexCount = sweep.Vertices.size();
  result.DegenerateVertexCount = sweep.DegenerateVertices;
  TileGatherer(sweep, points.size(), scale).Into(result);
  return result;
}

} // namespace tessera
