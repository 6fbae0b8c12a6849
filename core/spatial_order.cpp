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

// LSD radix sort on the low `bits` bits of the keys, 11 bits per pass; stable,
// so equal keys keep their (ascending id) order and the result does not depend
// on anything but the input.
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

// The same on keys packed above the ids in one 64-bit word: half the memory traffic.
void RadixSortPacked(std::vector<std::uint64_t>& items, int lowBit, int bits)
{
  constexpr int DigitBits = 11;
  constexpr std::size_t Buckets = std::size_t(1) << DigitBits;
  std::vector<std::uint64_t> buffer(items.size());
  std::vector<std::size_t> count(Buckets);
  for (int shift = lowBit; shift < lowBit + bits; shift += DigitBits)
  {
    std::fill(count.begin(), count.end(), 0);
    for (const std::uint64_t item : items)
    {
      ++count[(item >> shift) & (Buckets - 1)];
    }
    std::size_t sum = 0;
    for (std::size_t& c : count)
    {
      const std::size_t here = c;
      c = sum;
      sum += here;
    }
    for (const std::uint64_t item : items)
    {
      buffer[count[(item >> shift) & (Buckets - 1)]++] = item;
    }
    items.swap(buffer);
  }
}

// Number of BRIO rounds: the first round keeps at least ~64 points so that tiny
// rounds do not waste a pass each.
int RoundCount(std::size_t n)
{
  int rounds = 1;
  while (rounds < 24 && (n >> rounds) >= 64)
  {
    ++rounds;
  }
  return rounds;
}

// Grid resolution: about 4 cells per point along the curve is enough for
// locality; more bits only cost time.
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
  // Walk down the quadrant tree from the top bit. In each quadrant the curve is
  // the parent's curve, possibly transposed and/or reflected; the rotation
  // keeps (x, y) in the frame of the sub-curve. Quadrant digits along the
  // curve: (0,0) 0, (0,1) 1, (1,1) 2, (1,0) 3.
  std::uint32_t index = 0;
  for (int level = levels - 1; level >= 0; --level)
  {
    const std::uint32_t side = std::uint32_t(1) << level;
    const std::uint32_t rx = (x >> level) & 1U;
    const std::uint32_t ry = (y >> level) & 1U;
    index = (index << 2) | ((3U * rx) ^ ry);
    // Branch-free (the quadrant bits are random, a branch would mispredict half
    // the time): when ry == 0 the sub-curve is transposed, and also reflected
    // when rx == 1.
    const std::uint32_t low = side - 1;
    x &= low;
    y &= low;
    const std::uint32_t transpose = (ry ^ 1U) * 0xffffffffU;
    const std::uint32_t reflect = low & transpose & (0U - rx);
    x ^= reflect;
    y ^= reflect;
    const std::uint32_t swapped = (x ^ y) & transpose;
    x ^= swapped;
    y ^= swapped;
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

  int roundBits = 0;
  while ((1 << roundBits) < rounds)
  {
    ++roundBits;
  }
  const int keyBits = 2 * levels + roundBits;
  std::int32_t largestId = 0;
  for (const std::int32_t id : ids)
  {
    largestId = std::max(largestId, id);
  }
  int idBits = 1;
  while (idBits < 31 && (std::int64_t(1) << idBits) <= largestId)
  {
    ++idBits;
  }
  const auto key = [&](std::int32_t id)
  {
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
    return (round << (2 * levels)) | h;
  };
  order.resize(n);
  if (keyBits + idBits <= 64)
  {
    std::vector<std::uint64_t> packed(n);
    for (std::size_t k = 0; k < n; ++k)
    {
      packed[k] = (key(ids[k]) << idBits) | std::uint64_t(ids[k]);
    }
    RadixSortPacked(packed, idBits, keyBits);
    const std::uint64_t idMask = (std::uint64_t(1) << idBits) - 1;
    for (std::size_t k = 0; k < n; ++k)
    {
      order[k] = std::int32_t(packed[k] & idMask);
    }
    return order;
  }
  std::vector<KeyedId> items(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    items[k] = { key(ids[k]), ids[k] };
  }
  RadixSortByKey(items, keyBits);
  for (std::size_t k = 0; k < n; ++k)
  {
    order[k] = items[k].Id;
  }
  return order;
}

} // namespace tessera
