// The effective constraints of a window by an angular sweep (the half-plane intersection of
// sorted normals, kept in a deque), with exact decisions only, and a certificate that the answer
// is the window's before it is given.
//
// The constraints are sorted by the angle of their outward normals; of those pointing the same
// way only the tightest is kept (the first given of equally tight ones). Taken in that order,
// each new constraint k pops from either end of the deque the lines whose corner with their
// neighbour does not lie strictly inside k: their edge would have no length.
//
// (With e before f at the back of the deque, and k after both in angle: where the corner of e
// and f lies on or beyond k's line, f's line, between e's and k's, keeps no stretch of positive
// length inside both, so f is popped, and e is then tested the same way against its neighbour.)
//
// The sweep is known to go wrong for empty or unbounded windows, so nothing it finds is taken on
// trust. The lines left, E, must (a) turn left by less than half a turn from each to the next, all
// the way round, (b) each keep an edge of positive length between its neighbours, and (c) leave
// every other constraint holding the polygon: tested at the polygon's corner that lies furthest
// along that constraint's normal, the corner between the two lines of E whose normals bracket its
// normal (found by a binary search on the angle). Then E's polygon is a bounded convex polygon
// with an interior, every constraint holds it, and every line of E keeps its edge: E is exactly
// the set of effective constraints.

#include "constraint_sweep.h"

#include "half_plane_predicates.h"

#include <algorithm>
#include <numeric>

namespace tessera
{
namespace
{

/// The constraints sorted by angle from constraint 0's normal, one per direction: the tightest,
/// of equally tight ones the first given.
std::vector<std::size_t> TightestByAngle(const std::vector<HalfPlane>& h, const AngleFrom& angle)
{
  std::vector<std::size_t> order(h.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(
    order.begin(), order.end(), [&](std::size_t p, std::size_t q) { return angle(h[p], h[q]); });
  std::vector<std::size_t> lines;
  for (const std::size_t k : order)
  {
    if (lines.empty() || angle(h[lines.back()], h[k]))
    {
      lines.push_back(k); // a new direction
    }
    else if (ParallelOffsetSign(h[lines.back()], h[k]) > 0)
    {
      lines.back() = k; // the kept line lies outside k: k is tighter
    }
  }
  return lines;
}

/// The lines whose edges survive the sweep, in angular order; empty where the sweep met lines
/// that do not turn left by less than half a turn (an unbounded or empty window).
std::vector<std::size_t> Sweep(const std::vector<HalfPlane>& h,
  const std::vector<std::size_t>& lines)
{
  std::vector<std::size_t> deque(lines.size());
  std::size_t head = 0, tail = 0; // the deque is deque[head .. tail)
  const auto turnsLeft = [&](std::size_t p, std::size_t q) { return NormalTurn(h[p], h[q]) > 0; };
  for (const std::size_t k : lines)
  {
    while (tail - head >= 2)
    {
      const std::size_t e = deque[tail - 2], f = deque[tail - 1];
      if (!turnsLeft(e, f))
      {
        return {};
      }
      if (ValueAtCrossing(h[e], h[f], h[k]) < 0)
      {
        break;
      }
      --tail;
    }
    while (tail - head >= 2)
    {
      const std::size_t e = deque[head], f = deque[head + 1];
      if (!turnsLeft(e, f))
      {
        return {};
      }
      if (ValueAtCrossing(h[e], h[f], h[k]) < 0)
      {
        break;
      }
      ++head;
    }
    deque[tail++] = k;
  }
  // The last lines against the first, and the first against the last.
  while (tail - head >= 3 &&
    ValueAtCrossing(h[deque[tail - 2]], h[deque[tail - 1]], h[deque[head]]) >= 0)
  {
    --tail;
  }
  while (tail - head >= 3 &&
    ValueAtCrossing(h[deque[head]], h[deque[head + 1]], h[deque[tail - 1]]) >= 0)
  {
    ++head;
  }
  return std::vector<std::size_t>(
    deque.begin() + std::ptrdiff_t(head), deque.begin() + std::ptrdiff_t(tail));
}

/// Checks (a) and (b) of the certificate (see the top): a bounded convex polygon whose every line
/// keeps an edge of positive length.
bool IsBoundedPolygon(const std::vector<HalfPlane>& h, const std::vector<std::size_t>& e)
{
  const std::size_t m = e.size();
  if (m < 3)
  {
    return false;
  }
  for (std::size_t k = 0; k < m; ++k)
  {
    const HalfPlane& before = h[e[(k + m - 1) % m]];
    const HalfPlane& line = h[e[k]];
    const HalfPlane& after = h[e[(k + 1) % m]];
    if (NormalTurn(line, after) <= 0 || ValueAtCrossing(before, line, after) >= 0)
    {
      return false;
    }
  }
  return true;
}

/// Check (c): constraint j holds the polygon of the lines e (angular order), tested at the corner
/// furthest along j's normal.
bool HoldsPolygon(const std::vector<HalfPlane>& h,
  const std::vector<std::size_t>& e,
  const AngleFrom& angle,
  std::size_t j)
{
  const std::size_t m = e.size();
  // The first line of e whose normal lies beyond j's: the furthest corner is where the line
  // before it meets it.
  const std::size_t after = static_cast<std::size_t>(
    std::upper_bound(
      e.begin(), e.end(), j, [&](std::size_t p, std::size_t q) { return angle(h[p], h[q]); }) -
    e.begin());
  const std::size_t line = after % m, before = (after + m - 1) % m;
  return ValueAtCrossing(h[e[before]], h[e[line]], h[j]) <= 0;
}

} // namespace

std::optional<std::vector<bool>> EffectiveBySweep(const std::vector<HalfPlane>& constraints)
{
  const std::size_t n = constraints.size();
  if (n < 3)
  {
    return std::nullopt;
  }
  const AngleFrom angle(constraints[0]);
  const std::vector<std::size_t> kept = Sweep(constraints, TightestByAngle(constraints, angle));
  if (!IsBoundedPolygon(constraints, kept))
  {
    return std::nullopt;
  }
  std::vector<bool> effective(n, false);
  for (const std::size_t k : kept)
  {
    effective[k] = true;
  }
  for (std::size_t j = 0; j < n; ++j)
  {
    if (!effective[j] && !HoldsPolygon(constraints, kept, angle, j))
    {
      return std::nullopt;
    }
  }
  return effective;
}

} // namespace tessera
