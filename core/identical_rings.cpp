// IdenticalRingPairs: each ring in a canonical order (from its smallest vertex, the way round that
// comes to the smaller neighbour first), the rings sorted by that order, equal neighbours paired.
#include "identical_rings.h"

#include "polygon_validation.h"
#include "predicates.h"

#include <algorithm>
#include <cmath>

namespace tessera
{
namespace
{
bool Before(const Point2& a, const Point2& b)
{
  return a.x != b.x ? a.x < b.x : a.y < b.y;
}

/// The ring's vertices without repeated consecutive ones (cyclically), in canonical order: the
/// sequence that starts at its smallest vertex, the way round that comes to the smaller neighbour
/// first. Empty for a ring with a coordinate that is not finite, of fewer than three vertices
/// left, or that passes through its smallest vertex twice (it touches itself, which validation
/// refuses; reading it from each pass would cost O(n) per pass).
std::vector<Point2> CanonicalRing(const Point2* ring, std::size_t count)
{
  std::vector<Point2> kept;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (!std::isfinite(ring[k].x) || !std::isfinite(ring[k].y))
    {
      return {};
    }
    if (kept.empty() || !(ring[k] == kept.back()))
    {
      kept.push_back(ring[k]);
    }
  }
  while (kept.size() > 1 && kept.front() == kept.back())
  {
    kept.pop_back();
  }
  const std::size_t n = kept.size();
  if (n < 3)
  {
    return {};
  }
  const std::size_t start =
    std::size_t(std::min_element(kept.begin(), kept.end(), Before) - kept.begin());
  if (std::count(kept.begin(), kept.end(), kept[start]) > 1)
  {
    return {};
  }
  // From the smallest vertex towards its smaller neighbour; where both neighbours are one point
  // (the ring goes there and back), the smaller of the two whole readings.
  std::vector<Point2> canonical(n), backwards(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    canonical[k] = kept[(start + k) % n];
    backwards[k] = kept[(start + n - k) % n];
  }
  if (std::lexicographical_compare(
        backwards.begin(), backwards.end(), canonical.begin(), canonical.end(), Before))
  {
    canonical.swap(backwards);
  }
  return canonical;
}

/// Whether copies of one ring (copies: their indices, ascending) cancel in pairs as a hole and
/// the island that fills it: the first lies inside an odd number of the other rings (the copies
/// aside), so its region is outside the rest and each pair adds it back. Copies of an outer
/// boundary would take their region away instead: not paired, so validation refuses them as a
/// ring given twice. The point tested is the middle of an edge of the ring that lies on no other
/// ring (rings may touch and share stretches).
bool IsHoleAndIsland(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices,
  const std::vector<std::size_t>& copies)
{
  const std::size_t r = copies.front();
  const Point2* ring = vertices.data() + offsets[r];
  const std::size_t count = offsets[r + 1] - offsets[r];
  for (std::size_t k = 0; k < count; ++k)
  {
    const Point2 a = ring[k], b = ring[(k + 1) % count];
    if (a == b)
    {
      continue;
    }
    const Point2 p{ a.x + 0.5 * (b.x - a.x), a.y + 0.5 * (b.y - a.y) };
    std::size_t around = 0;
    bool onAnother = false;
    for (std::size_t t = 0; t + 1 < offsets.size() && !onAnother; ++t)
    {
      if (std::binary_search(copies.begin(), copies.end(), t))
      {
        continue;
      }
      const Point2* other = vertices.data() + offsets[t];
      const std::size_t n = offsets[t + 1] - offsets[t];
      for (std::size_t j = 0; j < n && !onAnother; ++j)
      {
        // p on c-d, or a-b along c-d (p, rounded, might miss a shared stretch by an ulp)
        const Point2& c = other[j];
        const Point2& d = other[(j + 1) % n];
        onAnother = SegmentsIntersect(p, p, c, d) ||
          (orient2d(c, d, a) == 0 && orient2d(c, d, b) == 0 && SegmentsIntersect(a, b, c, d));
      }
      around += !onAnother && RingWinding(other, n, p) % 2 != 0 ? 1 : 0;
    }
    if (!onAnother)
    {
      return around % 2 == 1;
    }
  }
  return false; // every edge lies along other rings: left to validation
}
} // namespace

std::vector<std::pair<std::size_t, std::size_t>> IdenticalRingPairs(
  const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices)
{
  std::vector<std::vector<Point2>> canonical;
  std::vector<std::size_t> order;
  for (std::size_t r = 0; r + 1 < offsets.size(); ++r)
  {
    canonical.push_back(CanonicalRing(vertices.data() + offsets[r], offsets[r + 1] - offsets[r]));
    if (!canonical.back().empty())
    {
      order.push_back(r);
    }
  }
  const auto less = [&canonical](std::size_t a, std::size_t b)
  {
    const std::vector<Point2>& p = canonical[a];
    const std::vector<Point2>& q = canonical[b];
    if (p.size() != q.size())
    {
      return p.size() < q.size();
    }
    return std::lexicographical_compare(p.begin(), p.end(), q.begin(), q.end(), Before);
  };
  // Stable: identical rings stay in ring order, so the first two of each group pair up.
  std::stable_sort(order.begin(), order.end(), less);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<std::size_t> copies;
  for (std::size_t k = 0; k < order.size();)
  {
    std::size_t end = k + 1;
    while (end < order.size() && canonical[order[end]] == canonical[order[k]])
    {
      ++end;
    }
    copies.assign(order.begin() + std::ptrdiff_t(k), order.begin() + std::ptrdiff_t(end));
    if (copies.size() >= 2 && IsHoleAndIsland(offsets, vertices, copies))
    {
      for (std::size_t c = 0; c + 1 < copies.size(); c += 2) // (ascending: a stable sort)
      {
        pairs.push_back({ copies[c], copies[c + 1] });
      }
    }
    k = end;
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

} // namespace tessera
