#include "fan_diagonals.h"

#include "display_pieces.h"
#include "polygon_validation.h" // SegmentsIntersect
#include "predicates.h"

#include <cstddef>
#include <utility>

namespace tessera
{
namespace
{

constexpr std::size_t MaxParts = 64;

/// Whether the segment from vertex i to b leaves i into the ring's interior (O'Rourke's in-cone
/// test, exact): between the edges at i, on the inside of the angle they make.
bool IntoInterior(const std::vector<Point2>& ring, std::size_t i, const Point2& b)
{
  const std::size_t n = ring.size();
  const Point2& a = ring[i];
  const Point2& previous = ring[i == 0 ? n - 1 : i - 1];
  const Point2& next = ring[i + 1 == n ? 0 : i + 1];
  if (orient2d(a, next, previous) >= 0) // a convex corner
  {
    return orient2d(a, b, previous) > 0 && orient2d(b, a, next) > 0;
  }
  return !(orient2d(a, b, next) >= 0 && orient2d(b, a, previous) >= 0);
}

/// Whether vertices i and j (not neighbours) join by a diagonal: inside the ring at both ends,
/// meeting no edge that is not at i or j. Each edge tested is taken from budget; false once it
/// runs out.
bool IsDiagonal(const std::vector<Point2>& ring, std::size_t i, std::size_t j, std::size_t& budget)
{
  const std::size_t n = ring.size();
  if (!IntoInterior(ring, i, ring[j]) || !IntoInterior(ring, j, ring[i]))
  {
    return false;
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::size_t next = k + 1 == n ? 0 : k + 1;
    if (k == i || k == j || next == i || next == j)
    {
      continue;
    }
    if (budget == 0)
    {
      return false;
    }
    --budget;
    if (SegmentsIntersect(ring[i], ring[j], ring[k], ring[next]))
    {
      return false;
    }
  }
  return true;
}

/// A diagonal (i, j) of the ring that halves its vertices as near as one does: vertices i and
/// i + n/2 from every start, then farther from the half (an eighth, a quarter of n either way),
/// within 16 n + 4096 edge tests (a candidate is mostly ruled out by its ends' angles, at no
/// cost). (n, n) when none is found.
std::pair<std::size_t, std::size_t> HalvingDiagonal(const std::vector<Point2>& ring)
{
  const std::size_t n = ring.size();
  std::size_t budget = 16 * n + 4096;
  for (const std::size_t offset : { n / 2, n / 2 - n / 8, n / 2 + n / 8, n / 4, n - n / 4 })
  {
    if (offset < 2 || offset > n - 2)
    {
      continue; // (neighbours or the vertex itself)
    }
    for (std::size_t i = 0; i < n && budget > 0; ++i)
    {
      const std::size_t j = (i + offset) % n;
      if (IsDiagonal(ring, i, j, budget))
      {
        return { i, j };
      }
    }
  }
  return { n, n };
}

/// Vertices from .. to of ring, walking on (to included).
std::vector<Point2> Stretch(const std::vector<Point2>& ring, std::size_t from, std::size_t to)
{
  std::vector<Point2> part;
  for (std::size_t k = from;; k = k + 1 == ring.size() ? 0 : k + 1)
  {
    part.push_back(ring[k]);
    if (k == to)
    {
      return part;
    }
  }
}

/// ring as fans (parts), split while splitsLeft lasts (a split makes one part more).
void Split(std::vector<Point2> ring,
  std::vector<std::vector<Point2>>& parts,
  std::size_t& splitsLeft)
{
  if (ring.size() < 4 || StartAtFanApex(ring) || splitsLeft == 0)
  {
    parts.push_back(std::move(ring));
    return;
  }
  const auto [i, j] = HalvingDiagonal(ring);
  if (i == ring.size())
  {
    parts.push_back(std::move(ring));
    return;
  }
  --splitsLeft;
  Split(Stretch(ring, i, j), parts, splitsLeft);
  Split(Stretch(ring, j, i), parts, splitsLeft);
}

} // namespace

std::vector<std::vector<Point2>> FansByDiagonals(const std::vector<Point2>& ring)
{
  std::vector<std::vector<Point2>> parts;
  std::size_t splitsLeft = MaxParts - 1;
  Split(ring, parts, splitsLeft);
  return parts;
}

} // namespace tessera
