#pragma once
// Exact predicates for the window decisions of the tile derivation (tiles.h): where a circumcentre
// lies relative to a window line, and in which order a bisector meets window lines. Like
// predicates.h they evaluate a polynomial in the input doubles with a floating-point filter (a
// static bound proportional to the permanent) and fall back to exact expansion arithmetic.
// Constructions (the rounded centre, the crossing points) stay in double; only signs come from
// here, so every topological decision of the tiles is exact.
//
// Range. The exact tier forms the products with fma, exact unless a product overflows or falls
// below about 2^-969: coordinates and coefficients within about 1e-60 .. 1e60 (nonzero) are safe,
// far beyond the 2^30 offsets and 1e-9 / 1e9 scalings the project tests. A caller with coordinates
// outside it scales points and window with ScaleIntoExactRange (window.h) first, as the
// tessellation filters do.
//
// Bisector parametrisation: for points a, b the bisector is m + t * d with m = (a + b) / 2 and
// d = (b - a) turned anticlockwise, d = (a.y - b.y, b.x - a.x).

#include "geometry.h"
#include "window.h"

namespace tessera
{

/// Sign of h.a * x + h.b * y + h.c at the circumcentre (x, y) of p, q, r (not collinear).
int CircumcentreSide(const HalfPlane& h, const Point2& p, const Point2& q, const Point2& r);

/// Sign of h.a * d.x + h.b * d.y for the bisector direction d of a, b: > 0 when moving along d
/// leaves the half-plane (crosses the line outwards), < 0 when it enters, 0 when parallel.
int BisectorDirectionSign(const HalfPlane& h, const Point2& a, const Point2& b);

/// Sign of h.a * x + h.b * y + h.c at the midpoint of a and b.
int MidpointSide(const HalfPlane& h, const Point2& a, const Point2& b);

/// Sign of t_h - t_g, where the bisector of a, b meets the line of h at parameter t_h and the
/// line of g at t_g. Both lines must cross the bisector (BisectorDirectionSign != 0).
int CompareBisectorCrossings(const HalfPlane& h,
  const HalfPlane& g,
  const Point2& a,
  const Point2& b);

} // namespace tessera
