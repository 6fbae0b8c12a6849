#include "tile_edges.h"

#include "circumcentre.h"
#include "polygon_area.h"
#include "window_predicates.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera
{
namespace tiles_detail
{

// The bound is first order in the roundings of the differences, squares, products and quotient,
// times a safety factor of 4: the exact circle comparison only uses it to skip pairs of triangles
// whose centres are certainly different.
Point2 Circumcentre(const Point2& a, const Point2& b, const Point2& c, double& error)
{
  const CircumcentreTerms t = CircumcentreOffset(a, b, c);
  const Point2& o = t.Origin;
  const double bx = t.bx, by = t.by, cx = t.cx, cy = t.cy, b2 = t.b2, c2 = t.c2, d = t.d;
  const double ux = t.ux, uy = t.uy;
  const double condition = 2.0 * t.products / std::fabs(d);
  const double spread = 2.0 *
    (std::fabs(cy) * b2 + std::fabs(by) * c2 + std::fabs(bx) * c2 + std::fabs(cx) * b2) /
    std::fabs(d);
  constexpr double unit = 0x1p-53;
  error = 4.0 * 16.0 * unit *
    (spread + (std::fabs(ux) + std::fabs(uy)) * (condition + 1.0) + std::fabs(o.x) +
      std::fabs(o.y));
  if (!std::isfinite(error))
  {
    error = std::numeric_limits<double>::infinity();
  }
  return { o.x + ux, o.y + uy };
}

Point2 FaceCentre(const std::vector<Point2>& pts,
  const std::int32_t* ids,
  std::size_t count,
  double& error)
{
  // The first three by ComesFirst, in one pass: the three kept are sorted, and a further id that
  // comes before the last of them takes its place.
  std::int32_t first[3] = { ids[0], ids[1], ids[2] };
  SortByCoordinates(pts.data(), first[0], first[1], first[2]);
  for (std::size_t k = 3; k < count; ++k)
  {
    if (ComesFirst(pts[ids[k]], pts[first[2]]))
    {
      first[2] = ids[k];
      SortByCoordinates(pts.data(), first[0], first[1], first[2]);
    }
  }
  return Circumcentre(pts[first[0]], pts[first[1]], pts[first[2]], error);
}

namespace
{
// The exact side of face's centre: any three of its points span its circle.
int FaceSide(const Tess& tess, std::int32_t face, const HalfPlane& h)
{
  const auto& org = tess.Origin();
  const std::vector<Point2>& pts = tess.Points();
  return CircumcentreSide(h, pts[org[3 * face]], pts[org[3 * face + 1]], pts[org[3 * face + 2]]);
}
} // namespace

// Whether the centre of the face with representative triangle `face` lies
// strictly inside the window, exactly: the rounded centre c and its error bound
// settle almost every face, CircumcentreSide the rest.
bool CentreInside(const Tess& tess, std::int32_t face, const Point2& c, double error)
{
  if (tess.GetWindow().CertainlyContains(c, error))
  {
    return true; // most centres, in an axis-aligned rectangle: a few comparisons
  }
  constexpr double unit = 0x1p-53;
  for (const HalfPlane& h : tess.GetWindow().EffectiveConstraints())
  {
    const double ax = h.a * c.x, by = h.b * c.y;
    const double value = (ax + by) + h.c;
    // The centre's coordinates are within `error` of the true ones; the evaluation adds at most
    // 3 roundings. NaN or infinity fails both tests and goes to the exact predicate.
    const double bound = (std::fabs(h.a) + std::fabs(h.b)) * error +
      4.0 * unit * ((std::fabs(ax) + std::fabs(by)) + std::fabs(h.c));
    if (value < -bound)
    {
      continue;
    }
    if (value > bound || FaceSide(tess, face, h) >= 0)
    {
      return false;
    }
  }
  return true;
}

namespace
{

// The window lines that bound the bisector of a and b: Lower gives L (entered along d), Upper
// gives U (left along d); a Corner flag tells that an adjacent line crosses there too.
struct WindowSpan
{
  int Lower = -1, Upper = -1;
  bool LowerCorner = false, UpperCorner = false;
};

// False when the bisector misses the open window: parallel to a line and on or outside it, or
// no entry or exit, or L >= U.
bool FindWindowSpan(const std::vector<HalfPlane>& constraints,
  const Point2& pa,
  const Point2& pb,
  WindowSpan& span)
{
  const int count = int(constraints.size());
  for (int k = 0; k < count; ++k)
  {
    const HalfPlane& h = constraints[k];
    const int direction = BisectorDirectionSign(h, pa, pb);
    if (direction == 0)
    {
      if (MidpointSide(h, pa, pb) >= 0)
      {
        return false; // parallel, on or outside the line
      }
      continue;
    }
    int& best = direction > 0 ? span.Upper : span.Lower;
    bool& corner = direction > 0 ? span.UpperCorner : span.LowerCorner;
    if (best < 0)
    {
      best = k;
      corner = false;
      continue;
    }
    // Exit: the smallest crossing; entry: the largest.
    const int order = CompareBisectorCrossings(h, constraints[best], pa, pb) * direction;
    if (order < 0)
    {
      best = k;
      corner = false;
    }
    else if (order == 0)
    {
      // A tie at a corner: keep the earlier line on exit, the later on entry.
      const bool kAfterBest = (best + 1) % count == k;
      const bool kBeforeBest = (k + 1) % count == best;
      if ((direction > 0 && kBeforeBest) || (direction < 0 && kAfterBest))
      {
        best = k;
      }
      corner = corner || kAfterBest || kBeforeBest;
    }
  }
  return span.Lower >= 0 && span.Upper >= 0 &&
    CompareBisectorCrossings(constraints[span.Lower], constraints[span.Upper], pa, pb) < 0;
}

// Where the bisector m + t * d of a and b meets the line of h (only for edges that end on the
// window). d is scaled by a power of two to a largest component in [1, 2): exact, so the
// crossing's bits are unchanged (scaling by 2^k commutes with rounding), but a direction of
// subnormal size (points a subnormal distance apart) no longer sends t to infinity, where t * 0
// made a NaN.
Point2 BisectorCrossing(const Point2& pa, const Point2& pb, const HalfPlane& h)
{
  const double mx = 0.5 * (pa.x + pb.x), my = 0.5 * (pa.y + pb.y);
  const int scale = -std::ilogb(std::max(std::fabs(pb.y - pa.y), std::fabs(pb.x - pa.x)));
  const double dx = std::ldexp(-(pb.y - pa.y), scale), dy = std::ldexp(pb.x - pa.x, scale);
  // An axis-aligned side keeps its coordinate exactly (-c/a or -c/b, one rounding), so a
  // rectangle's tiles have straight sides; only the other coordinate comes from the bisector.
  // The distance from the midpoint is taken as the mean of the distances from the two points
  // (exact differences where the points are near the side), not from the rounded midpoint:
  // that rounding, times a steep bisector's slope, put a crossing 2^26 ulps off (points 2e-9
  // apart across, 2^-54 along; the Brassel-Reif sweep, which writes it so, was an ulp off).
  if (h.b == 0.0 && dx != 0.0)
  {
    const double x = -h.c / h.a;
    return Point2{ x, my + 0.5 * ((x - pa.x) + (x - pb.x)) / dx * dy };
  }
  if (h.a == 0.0 && dy != 0.0)
  {
    const double y = -h.c / h.b;
    return Point2{ mx + 0.5 * ((y - pa.y) + (y - pb.y)) / dy * dx, y };
  }
  const double t = -(h.a * mx + h.b * my + h.c) / (h.a * dx + h.b * dy);
  return Point2{ mx + t * dx, my + t * dy };
}

// One end of the clipped edge: the face's centre where it lies inside the window line's crossing
// (versus > 0 for the low end, < 0 for the high end, as ClipCanonical computes them), the crossing
// or the window corner beyond it, and the centre labelled with the line when it lies on it.
EdgeEnd ClippedEnd(const Tess& tess,
  const Point2& pa,
  const Point2& pb,
  const FaceView& face,
  int versus,
  int line,
  bool corner,
  bool exit)
{
  const int beyond = exit ? versus : -versus; // > 0: the centre lies past the line
  if (face.Face >= 0 && beyond < 0)
  {
    return { face.Centre, -1, face.Face };
  }
  const std::vector<HalfPlane>& constraints = tess.GetWindow().EffectiveConstraints();
  if (corner)
  {
    // Window corner k is where constraint k-1 meets k: for a tie between k and k+1 it is k+1.
    const int count = int(constraints.size());
    const int cornerIndex = exit ? (line + 1) % count : line;
    return { tess.GetWindow().Vertices()[std::size_t(cornerIndex)], line, -2 - cornerIndex };
  }
  return face.Face < 0 || beyond > 0
    ? EdgeEnd{ BisectorCrossing(pa, pb, constraints[line]), line, -1 }
    : EdgeEnd{ face.Centre, line, face.Face };
}

// The part inside the window of the tile edge of a (lower id) with b: the
// bisector, parametrised as m + t * d with m the midpoint and d = (b - a)
// turned anticlockwise, from the centre of loFace (right of a->b; -1 for a
// ghost: t = -infinity) to the centre of hiFace (left of a->b), t_lo < t_hi.
//
// Every decision is exact (window_predicates.h): the window meets the bisector
// in the open interval (L, U), L the last crossing of a line entered along d,
// U the first crossing of a line left; the edge is kept iff
// max(t_lo, L) < min(t_hi, U), i.e. the open Voronoi edge meets the open
// window in a segment of positive length. A centre is compared with a crossing
// through the sign of the line at the centre: the centre lies on the bisector,
// so h(centre) = h(m) + t_centre h(d) = (t_centre - t_line) h(d).
// Only the coordinates (centre bits, crossings m + t d) are rounded.
//
// Ends exactly on the window boundary: an end at a face centre on a line
// keeps the centre's bits (every tile meeting there shares them) but carries
// the line, so the polygon follows the window from there. Where the end is a
// window corner (two lines cross the bisector at the same point) it takes the
// corner's bits; leaving, it is labelled with the earlier of the two lines and
// entering with the later, so the walk along the boundary from an exit to the
// next entry never goes round the window the wrong way (it only repeats the
// corner, which AssemblePolygon drops).
bool ClipCanonical(const Tess& tess,
  std::int32_t a,
  std::int32_t b,
  const FaceView& lo,
  const FaceView& hi,
  TileEdge& out)
{
  const std::int32_t loFace = lo.Face, hiFace = hi.Face;
  const bool loInside = loFace >= 0 && lo.Inside;
  const bool hiInside = hiFace >= 0 && hi.Inside;
  if (loInside && hiInside)
  {
    out.Lo = { lo.Centre, -1, loFace };
    out.Hi = { hi.Centre, -1, hiFace };
    return true;
  }
  const Point2& pa = tess.Points()[a];
  const Point2& pb = tess.Points()[b];
  const auto& constraints = tess.GetWindow().EffectiveConstraints();
  WindowSpan span;
  if (!FindWindowSpan(constraints, pa, pb, span))
  {
    return false;
  }
  const HalfPlane& hl = constraints[span.Lower];
  const HalfPlane& hu = constraints[span.Upper];
  // Centre vs L: sign(t_centre - L) = -FaceSide(face, hl) (the line is entered along d);
  // centre vs U: sign(t_centre - U) = FaceSide(face, hu).
  int loVsL = 1, hiVsU = -1;
  if (loFace >= 0 && !loInside)
  {
    if (FaceSide(tess, loFace, hu) >= 0)
    {
      return false; // t_lo >= U
    }
    loVsL = -FaceSide(tess, loFace, hl);
  }
  if (hiFace >= 0 && !hiInside)
  {
    if (FaceSide(tess, hiFace, hl) >= 0)
    {
      return false; // t_hi <= L
    }
    hiVsU = FaceSide(tess, hiFace, hu);
  }
  out.Lo = ClippedEnd(tess, pa, pb, lo, loVsL, span.Lower, span.LowerCorner, false);
  out.Hi = ClippedEnd(tess, pa, pb, hi, hiVsU, span.Upper, span.UpperCorner, true);
  return true;
}
} // namespace

bool ClipEdge(const Tess& tess,
  std::int32_t from,
  std::int32_t to,
  const FaceView& right,
  const FaceView& left,
  TileEdge& out)
{
  const std::vector<Point2>& pts = tess.Points();
  if (ComesFirst(pts[from], pts[to]))
  {
    return ClipCanonical(tess, from, to, right, left, out);
  }
  TileEdge reversed;
  if (!ClipCanonical(tess, to, from, left, right, reversed))
  {
    return false;
  }
  out.Lo = reversed.Hi;
  out.Hi = reversed.Lo;
  return true;
}

// Returns the number of sides (contiguities with points and window edges), decided exactly.
std::int32_t AssemblePolygon(const Tess& tess,
  const std::vector<TileEdge>& edges,
  std::vector<Point2>& polygon)
{
  const std::vector<Point2>& corners = tess.GetWindow().Vertices();
  const int count = int(corners.size());
  polygon.clear();
  if (edges.empty())
  {
    polygon = corners;
    return count;
  }
  // Sides: one per tile edge, plus the window pieces between an exit and the next entry, counted
  // from the exact decisions (the rounded vertices may coincide where the true ones do not).
  std::int32_t sides = std::int32_t(edges.size());
  for (std::size_t s = 0; s < edges.size(); ++s)
  {
    const TileEdge& edge = edges[s];
    polygon.push_back(edge.Lo.P);
    if (edge.Hi.Constraint < 0)
    {
      continue; // a face centre: the next edge starts there
    }
    polygon.push_back(edge.Hi.P);
    const EdgeEnd& next = edges[(s + 1) % edges.size()].Lo;
    if (next.Constraint < 0 || (next.Where == edge.Hi.Where && next.Where != -1))
    {
      continue; // leaves and re-enters at one point: no window side
    }
    // Leave on constraint a, follow the window boundary through corners a+1 ..
    // b, re-enter on b: pieces of lines a .. b, less those of zero length (leaving
    // at corner a+1, or entering at corner b).
    const int exit = edge.Hi.Constraint;
    const int entry = next.Constraint;
    sides += (entry - exit + count) % count + 1;
    sides -= edge.Hi.Where == -2 - (exit + 1) % count ? 1 : 0;
    sides -= next.Where == -2 - entry ? 1 : 0;
    for (int k = exit; k != entry;)
    {
      k = (k + 1) % count;
      polygon.push_back(corners[k]);
    }
  }
  // Repeated vertices (an end exactly at a corner, or distinct ends rounded to
  // one point) are dropped.
  DropRepeatedVertices(polygon);
  return sides;
}

void AppendTile(TileSet& tiles,
  std::int32_t point,
  const std::vector<Point2>& polygon,
  std::int32_t sides)
{
  tiles.Vertices.insert(tiles.Vertices.end(), polygon.begin(), polygon.end());
  AppendTileColumns(tiles,
    point,
    std::int64_t(tiles.Vertices.size()),
    CompensatedPolygonArea(polygon.data(), polygon.size()),
    sides);
}

void AppendTileSet(TileSet& tiles, const TileSet& from)
{
  AppendTileColumns(tiles, from, std::int64_t(tiles.Vertices.size()));
  tiles.Vertices.insert(tiles.Vertices.end(), from.Vertices.begin(), from.Vertices.end());
}

TileSet JoinTileParts(std::vector<OwnCacheLines<TileSet>>& parts)
{
  TileSet tiles = std::move(parts.front().Value);
  for (std::size_t k = 1; k < parts.size(); ++k)
  {
    AppendTileSet(tiles, parts[k].Value);
  }
  return tiles;
}

} // namespace tiles_detail
} // namespace tessera
