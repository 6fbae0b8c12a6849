#include "spatial_order.h"

#include <algorithm>
#include <cmath>

namespace tessera
{
namespace
{

std::uint64_t SplitMix64(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

struct KeyedId
{
  std::uint64_t Key;
  std::int32_t Id;
};

// LSD radix sort on the low `bits` bits of the keys, 11 bits per pass; stable, so equal keys keep
// their (ascending id) order and the result does not depend on anything but the input.
void RadixSortByKey(std::vector<KeyedId>& items, int bits)
{
  constexpr int DigitBits = 11;
  constexpr std::size_t Buckets = std::size_t(1) << DigitBits;
  std::vector<KeyedId> buffer(items.size());
  std::vector<std::size_t> count(Buckets);
  for (int shift = 0; shift < bits; shift += DigitBits)
  {
    std::fill(count.begin(), count.end(), 0);
    for (const KeyedId& item : items)
    {
      ++count[(item.Key >> shift) & (Buckets - 1)];
    }
    std::size_t sum = 0;
    for (std::size_t& c : count)
    {
      const std::size_t here = c;
      c = sum;
      sum += here;
    }
    for (const KeyedId& item : items)
    {
      buffer[count[(item.Key >> shift) & (Buckets - 1)]++] = item;
    }
    items.swap(buffer);
  }
}

// Number of BRIO rounds: the first round keeps at least ~64 points so that tiny rounds do not
// waste a pass each.
int RoundCount(std::size_t n)
{
  int rounds = 1;
  while (rounds < 24 && (n >> rounds) >= 64)
  {
    ++rounds;
  }
  return rounds;
}

// Grid resolution: about 4 cells per point along the curve is enough for locality; more bits only
// cost time.
int LevelCount(std::size_t n)
{
  int levels = 1;
  while (levels < 16 && (std::size_t(1) << (2 * levels)) < 16 * n)
  {
    ++levels;
  }
  return levels;
}

} // namespace

std::uint32_t HilbertIndex(std::uint32_t x, std::uint32_t y, int levels)
{
  // Walk down the quadrant tree from the top bit. In each quadrant the curve is the parent's
  // curve, possibly transposed and/or reflected; the rotation keeps (x, y) in the frame of the
  // sub-curve. Quadrant digits along the curve: (0,0) 0, (0,1) 1, (1,1) 2, (1,0) 3.
  std::uint32_t index = 0;
  for (int level = levels - 1; level >= 0; --level)
  {
    const std::uint32_t side = std::uint32_t(1) << level;
    const std::uint32_t rx = (x >> level) & 1U;
    const std::uint32_t ry = (y >> level) & 1U;
    index = (index << 2) | ((3U * rx) ^ ry);
    if (ry == 0)
    {
      if (rx == 1)
      {
        x = side - 1 - (x & (side - 1));
        y = side - 1 - (y & (side - 1));
      }
      std::swap(x, y);
    }
    x &= side - 1;
    y &= side - 1;
  }
  return index;
}

std::vector<std::int32_t> BrioHilbertOrder(const std::vector<Point2>& points,
  const std::vector<std::int32_t>& ids,
  std::uint64_t seed)
{
  const std::size_t n = ids.size();
  std::vector<std::int32_t> order;
  if (n == 0)
  {
    return order;
  }
  double xmin = points[ids[0]].x, xmax = xmin, ymin = points[ids[0]].y, ymax = ymin;
  for (const std::int32_t id : ids)
  {
    xmin = std::min(xmin, points[id].x);
    xmax = std::max(xmax, points[id].x);
    ymin = std::min(ymin, points[id].y);
    ymax = std::max(ymax, points[id].y);
  }
  const int levels = LevelCount(n);
  const int rounds = RoundCount(n);
  const double cells = double(std::uint32_t(1) << levels);
  // One common scale for both axes keeps the curve's locality isotropic.
  const double extent = std::max(xmax - xmin, ymax - ymin);
  const double scale = extent > 0.0 ? (cells * (1.0 - 1e-12)) / extent : 0.0;
  const auto cell = [&](double v, double lo)
  {
    const double c = std::floor((v - lo) * scale);
    return std::uint32_t(std::min(std::max(c, 0.0), cells - 1.0));
  };

  std::vector<KeyedId> items(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::int32_t id = ids[k];
    // Trailing zeros of a hash: 0 with probability 1/2 (last round), 1 with 1/4, ...
    const std::uint64_t hash = SplitMix64(seed ^ (std::uint64_t(id) * 0x2545f4914f6cdd1dULL));
    int zeros = 0;
    while (zeros < rounds - 1 && ((hash >> zeros) & 1U) == 0)
    {
      ++zeros;
    }
    const std::uint64_t round = std::uint64_t(rounds - 1 - zeros);
    const std::uint32_t h =
      HilbertIndex(cell(points[id].x, xmin), cell(points[id].y, ymin), levels);
    items[k] = { (round << (2 * levels)) | h, id };
  }
  int roundBits = 0;
  while ((1 << roundBits) < rounds)
  {
    ++roundBits;
  }
  RadixSortByKey(items, 2 * levels + roundBits);
  order.resize(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    order[k] = items[k].Id;
  }
  return order;
}

} // namespace tessera
