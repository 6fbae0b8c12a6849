#pragma once
// Exact sign tests on the open half-planes a*x + b*y + c < 0 of a window (window.h), shared by
// the two ways of finding its effective constraints (window.cpp's pairwise test and
// constraint_sweep.h's sweep). Their sign conventions are sketched at the top of window.cpp.

#include "predicates.h"
#include "window.h"

namespace tessera
{

/// sign(x1 * y2 - y1 * x2), exactly.
inline int CrossSign(double x1, double y1, double x2, double y2)
{
  return orient2d(Point2{ x1, y1 }, Point2{ x2, y2 }, Point2{ 0.0, 0.0 });
}

/// The sign of the normals' cross product: positive when j's normal lies less than 180 degrees
/// anticlockwise of i's, 0 when they are parallel.
inline int NormalTurn(const HalfPlane& i, const HalfPlane& j)
{
  return CrossSign(i.a, i.b, j.a, j.b);
}

/// The sign of constraint j's value at the crossing of the lines of i and k: negative where the
/// crossing lies strictly inside j. 0 also when i and k are parallel (no crossing): callers test
/// that first.
inline int ValueAtCrossing(const HalfPlane& i, const HalfPlane& k, const HalfPlane& j)
{
  return determinant3_sign(i.a, i.b, i.c, k.a, k.b, k.c, j.a, j.b, j.c) * NormalTurn(i, k);
}

/// For parallel normals n_j = lambda n_i (lambda != 0): the sign of constraint j's value on the
/// line of i. Negative: the line of i lies strictly inside j.
inline int ParallelOffsetSign(const HalfPlane& i, const HalfPlane& j)
{
  // On L_i, a_i x + b_i y = -c_i, so j's value is c_j - lambda c_i with lambda = a_j / a_i, i.e.
  // (a_i c_j - a_j c_i) / a_i (or the same with b when a_i == 0).
  const auto signOf = [](double v) { return (v > 0.0) - (v < 0.0); };
  if (i.a != 0.0)
  {
    return CrossSign(i.a, i.c, j.a, j.c) * signOf(i.a);
  }
  return CrossSign(i.b, i.c, j.b, j.c) * signOf(i.b);
}

/// Whether parallel normals point the same way.
inline bool SameDirection(const HalfPlane& i, const HalfPlane& j)
{
  return i.a != 0.0 ? (i.a > 0.0) == (j.a > 0.0) : (i.b > 0.0) == (j.b > 0.0);
}

/// Orders constraints by the angle of their outward normals anticlockwise from ref's, ref's own
/// direction first: a strict weak ordering in which normals that point the same way are
/// equivalent.
class AngleFrom
{
public:
  explicit AngleFrom(const HalfPlane& ref)
    : Ref(ref)
  {
  }

  bool operator()(const HalfPlane& p, const HalfPlane& q) const
  {
    const int halfP = this->Half(p), halfQ = this->Half(q);
    if (halfP != halfQ)
    {
      return halfP < halfQ;
    }
    return NormalTurn(p, q) > 0; // (within a half turn, a left turn is a larger angle)
  }

private:
  /// 0 for normals at angles [0, 180) from ref's, 1 for [180, 360).
  int Half(const HalfPlane& h) const
  {
    const int c = NormalTurn(this->Ref, h);
    return (c > 0 || (c == 0 && SameDirection(this->Ref, h))) ? 0 : 1;
  }

  HalfPlane Ref;
};

} // namespace tessera
