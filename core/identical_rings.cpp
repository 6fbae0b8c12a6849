// IdenticalRingPairs: each ring in a canonical order (from its smallest vertex, the way round that
// comes to the smaller neighbour first), the rings sorted by that order, equal neighbours paired.
#include "identical_rings.h"

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
/// lexicographically smallest of the sequences that start at a smallest vertex, either way round.
/// Empty for a ring with a NaN coordinate or fewer than three vertices left.
std::vector<Point2> CanonicalRing(const Point2* ring, std::size_t count)
{
  std::vector<Point2> kept;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (std::isnan(ring[k].x) || std::isnan(ring[k].y))
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
  const Point2 smallest = *std::min_element(kept.begin(), kept.end(), Before);
  std::vector<Point2> best, candidate(n);
  for (std::size_t start = 0; start < n; ++start)
  {
    if (!(kept[start] == smallest))
    {
      continue;
    }
    for (const std::size_t step : { std::size_t(1), n - 1 }) // forwards, backwards
    {
      for (std::size_t k = 0; k < n; ++k)
      {
        candidate[k] = kept[(start + k * step) % n];
      }
      if (best.empty() ||
        std::lexicographical_compare(
          candidate.begin(), candidate.end(), best.begin(), best.end(), Before))
      {
        best = candidate;
      }
    }
  }
  return best;
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
  for (std::size_t k = 0; k + 1 < order.size();)
  {
    if (canonical[order[k]] == canonical[order[k + 1]])
    {
      pairs.push_back({ order[k], order[k + 1] });
      k += 2;
    }
    else
    {
      ++k;
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

} // namespace tessera
