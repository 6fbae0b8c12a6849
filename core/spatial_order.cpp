#include "spatial_order.h"

#include "parallel_chunks.h"
#include "radix_sort.h"
#include "uninitialized_allocator.h"

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

// Grid resolution: about 4 to 16 cells per point along the curve is enough for
// locality; more bits only cost time.
int LevelCount(std::size_t n)
{
  int levels = 1;
  while (levels < 16 && (std::size_t(1) << (2 * levels)) < 4 * n)
  {
    ++levels;
  }
  return levels;
}

} // namespace

namespace
{

// The curve in a sub-square is the parent's curve in a transformed frame; the transformations
// met are compositions of a transposition (bit 0 of the state) and a reflection of both axes
// (bit 1), which commute. One step reads one bit of x and of y in the current frame, emits the
// quadrant digit (0,0) 0, (0,1) 1, (1,1) 2, (1,0) 3 and updates the frame: when ry == 0 the
// sub-curve is transposed, and also reflected when rx == 1.
constexpr int TableBits = 4; // levels per table step

struct HilbertTable
{
  // Entry [state][x chunk][y chunk]: the 2 * TableBits digits in the low bits, the final state
  // above them.
  std::uint16_t Entry[4][1 << TableBits][1 << TableBits];

  HilbertTable()
    : Entry()
  {
    for (std::uint32_t start = 0; start < 4; ++start)
    {
      for (std::uint32_t xs = 0; xs < (1U << TableBits); ++xs)
      {
        for (std::uint32_t ys = 0; ys < (1U << TableBits); ++ys)
        {
          std::uint32_t state = start, digits = 0;
          for (int level = TableBits - 1; level >= 0; --level)
          {
            std::uint32_t rx = (xs >> level) & 1U, ry = (ys >> level) & 1U;
            if (state & 2U)
            {
              rx ^= 1U;
              ry ^= 1U;
            }
            if (state & 1U)
            {
              std::swap(rx, ry);
            }
            digits = (digits << 2) | ((3U * rx) ^ ry);
            if (ry == 0)
            {
              state ^= 1U | (rx << 1);
            }
          }
          this->Entry[start][xs][ys] = std::uint16_t(digits | (state << (2 * TableBits)));
        }
      }
    }
  }
};

const HilbertTable& TheHilbertTable()
{
  static const HilbertTable table;
  return table;
}

// HilbertIndex, TableBits levels per step (levels <= 16).
inline std::uint32_t HilbertIndexFast(const HilbertTable& table,
  std::uint32_t x,
  std::uint32_t y,
  int levels)
{
  // Zero levels appended below the cell refine every cell into the same sub-cell; the digits they
  // add are shifted out again at the end, which leaves the index at `levels` levels.
  const int steps = (levels + TableBits - 1) / TableBits;
  const int pad = steps * TableBits - levels;
  x <<= pad;
  y <<= pad;
  constexpr std::uint32_t Mask = (1U << TableBits) - 1U;
  std::uint32_t state = 0, index = 0;
  for (int step = steps - 1; step >= 0; --step)
  {
    const int shift = step * TableBits;
    const std::uint32_t entry = table.Entry[state][(x >> shift) & Mask][(y >> shift) & Mask];
    index = (index << (2 * TableBits)) | (entry & ((1U << (2 * TableBits)) - 1U));
    state = entry >> (2 * TableBits);
  }
  return index >> (2 * pad);
}

} // namespace

std::uint32_t HilbertIndex(std::uint32_t x, std::uint32_t y, int levels)
{
  return HilbertIndexFast(TheHilbertTable(), x, y, levels);
}

namespace
{
// The Hilbert index, on a 2^levels x 2^levels grid over box, of each point: one scale for both
// axes keeps the curve's locality isotropic, and a hair under cells / extent keeps the far side
// in the last cell. A box wider than the largest double makes the scale 0 and a coordinate's
// offset may be infinite (0 * inf = NaN): GridCell sends such a value to cell 0.
class CurveIndex
{
public:
  CurveIndex(const Box2& box, int levels)
    : Box(box)
    , Levels(levels)
    , Cells(std::uint32_t(1) << levels)
    , Scale(box.LargerSide() > 0.0 ? (double(this->Cells) * (1.0 - 1e-12)) / box.LargerSide() : 0.0)
    , Table(TheHilbertTable())
  {
  }

  std::uint32_t operator()(const Point2& p) const
  {
    return HilbertIndexFast(this->Table,
      GridCell((p.x - this->Box.XMin) * this->Scale, this->Cells),
      GridCell((p.y - this->Box.YMin) * this->Scale, this->Cells),
      this->Levels);
  }

private:
  Box2 Box;
  int Levels;
  std::uint32_t Cells;
  double Scale;
  const HilbertTable& Table;
};
} // namespace

namespace
{
// A run of more than this many points of one round in one grid cell is sorted along the finest
// curve (16 levels).
constexpr std::size_t CrowdedCell = 8;

// ids[begin, end) sorted along the finest curve over box (ties keep their order); returns each
// one's (curve index, id), in the new order.
std::vector<std::pair<std::uint32_t, std::int32_t>> SortByFinestCurve(const Point2* points,
  const Box2& box,
  std::int32_t* begin,
  std::int32_t* end)
{
  const CurveIndex index(box, 16);
  std::vector<std::pair<std::uint32_t, std::int32_t>> keyed;
  keyed.reserve(std::size_t(end - begin));
  for (const std::int32_t* id = begin; id != end; ++id)
  {
    keyed.emplace_back(index(points[*id]), *id);
  }
  std::stable_sort(
    keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t k = 0; k < keyed.size(); ++k)
  {
    begin[k] = keyed[k].second;
  }
  return keyed;
}

// The grid is sized for points that fill the box (about 4 cells a point); points on a few lines
// fill a few cells of it, some 2.5 sqrt(N) points each, left in their random order: the walk
// between two of them then crossed some sqrt(N) triangles (points on two lines 10 apart: 190
// million steps for 10^6 points, ten times the build of uniform points; even the finest grid
// over the whole box left 75 points a cell). Each such run of order[begin, end), which shares
// one cell, is sorted along the finest curve over the box of its own points: the order is then
// the coarse curve's from cell to cell and a finer one's within a crowded cell.
void SortCrowdedCell(const Point2* points, std::int32_t* begin, std::int32_t* end)
{
  Box2 box = BoundsOf(&points[*begin], 1);
  for (const std::int32_t* id = begin; id != end; ++id)
  {
    box.Extend(points[*id]);
  }
  SortByFinestCurve(points, box, begin, end);
}

// Sorts each crowded run of order along a curve of its own; keyOf(k) is the (round, cell) key
// of order[k].
template<typename KeyOf>
void SortCrowdedCells(const Point2* points, std::vector<std::int32_t>& order, const KeyOf& keyOf)
{
  std::size_t begin = 0;
  for (std::size_t k = 1; k <= order.size(); ++k)
  {
    if (k == order.size() || keyOf(k) != keyOf(begin))
    {
      if (k - begin > CrowdedCell)
      {
        SortCrowdedCell(points, order.data() + begin, order.data() + k);
      }
      begin = k;
    }
  }
}
} // namespace

void SortAlongHilbertCurve(const Point2* points, const Box2& box, std::vector<std::int32_t>& ids)
{
  const auto keyed = SortByFinestCurve(points, box, ids.data(), ids.data() + ids.size());
  SortCrowdedCells(points, ids, [&keyed](std::size_t k) { return keyed[k].first; });
}

Box2 BoundsOfIds(const std::vector<Point2>& points, const std::vector<std::int32_t>& ids)
{
  const std::vector<std::int32_t> bounds = parallel::ChunkBounds(
    std::int32_t(ids.size()), parallel::ThreadCount(std::int64_t(ids.size())));
  std::vector<Box2> boxes(bounds.size() - 1);
  parallel::RunChunks(bounds.size() - 1,
    [&](std::size_t c)
    {
      Box2 chunkBox = BoundsOf(&points[ids[bounds[c]]], 1);
      for (std::int32_t k = bounds[c]; k < bounds[c + 1]; ++k)
      {
        chunkBox.Extend(points[ids[k]]);
      }
      boxes[c] = chunkBox;
    });
  return UnionOf(boxes);
}

std::vector<std::int32_t> BrioHilbertOrder(const std::vector<Point2>& points,
  const std::vector<std::int32_t>& ids,
  std::uint64_t seed)
{
  if (ids.empty())
  {
    return {};
  }
  return BrioHilbertOrder(points, ids, BoundsOfIds(points, ids), seed);
}

namespace
{

/// The fewest bits, `least` or more (and at most 31), that hold every value below `limit`.
int BitsBelow(std::int64_t limit, int least)
{
  int bits = least;
  while (bits < 31 && (std::int64_t(1) << bits) < limit)
  {
    ++bits;
  }
  return bits;
}

/// A point's BRIO key: its round (the last round holds half the points, the one before a
/// quarter, ...), then its Hilbert index, 2 * levels bits below.
struct BrioKey
{
  BrioKey(const std::vector<Point2>& points, const Box2& box, std::size_t n, std::uint64_t seed)
    : Points(points.data())
    , Seed(seed)
    , Levels(LevelCount(n))
    , Rounds(RoundCount(n))
    , Curve(box, this->Levels)
  {
  }

  std::uint64_t operator()(std::int32_t id) const
  {
    // Trailing zeros of a hash: 0 with probability 1/2 (last round), 1 with 1/4, ...
    const std::uint64_t hash = SplitMix64(this->Seed ^ (std::uint64_t(id) * 0x2545f4914f6cdd1dULL));
    const int zeros = std::min(__builtin_ctzll(hash | (std::uint64_t(1) << 63)), this->Rounds - 1);
    const std::uint64_t round = std::uint64_t(this->Rounds - 1 - zeros);
    return (round << (2 * this->Levels)) | this->Curve(this->Points[id]);
  }

  int Bits() const { return 2 * this->Levels + BitsBelow(this->Rounds, 0); }

  const Point2* Points;
  std::uint64_t Seed;
  int Levels, Rounds;
  CurveIndex Curve;
};

/// The ids in key order, each key packed with its id (idBits) in one word: the keys computed on
/// the cores, which also first touch the array, and sorted on them from 500,000 ids.
void OrderByPackedKeys(const std::vector<Point2>& points,
  const std::vector<std::int32_t>& ids,
  const BrioKey& key,
  int idBits,
  std::vector<std::int32_t>& order)
{
  const std::size_t n = ids.size();
  const std::vector<std::int32_t> bounds =
    parallel::ChunkBounds(std::int32_t(n), parallel::ThreadCount(std::int64_t(n)));
  UninitializedVector<std::uint64_t> packed(n);
  parallel::RunChunks(bounds.size() - 1,
    [&](std::size_t c)
    {
      for (std::int32_t k = bounds[c]; k < bounds[c + 1]; ++k)
      {
        packed[k] = (key(ids[k]) << idBits) | std::uint64_t(ids[k]);
      }
    });
  RadixSortPacked(packed, idBits, key.Bits());
  const std::uint64_t idMask = (std::uint64_t(1) << idBits) - 1;
  parallel::RunChunks(bounds.size() - 1,
    [&](std::size_t c)
    {
      for (std::int32_t k = bounds[c]; k < bounds[c + 1]; ++k)
      {
        order[k] = std::int32_t(packed[k] & idMask);
      }
    });
  SortCrowdedCells(
    points.data(), order, [&packed, idBits](std::size_t k) { return packed[k] >> idBits; });
}

/// The ids in key order, keys and ids side by side (when they do not fit in one word together).
void OrderByKeyedIds(const std::vector<Point2>& points,
  const std::vector<std::int32_t>& ids,
  const BrioKey& key,
  std::vector<std::int32_t>& order)
{
  const std::size_t n = ids.size();
  std::vector<KeyedId> items(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    items[k] = { key(ids[k]), ids[k] };
  }
  RadixSortByKey(items, key.Bits());
  for (std::size_t k = 0; k < n; ++k)
  {
    order[k] = items[k].Id;
  }
  SortCrowdedCells(points.data(), order, [&items](std::size_t k) { return items[k].Key; });
}

} // namespace

std::vector<std::int32_t> BrioHilbertOrder(const std::vector<Point2>& points,
  const std::vector<std::int32_t>& ids,
  const Box2& box,
  std::uint64_t seed)
{
  const std::size_t n = ids.size();
  std::vector<std::int32_t> order;
  if (n == 0)
  {
    return order;
  }
  const std::int32_t largestId = *std::max_element(ids.begin(), ids.end());
  const BrioKey key(points, box, n, seed);
  const int idBits = BitsBelow(std::int64_t(largestId) + 1, 1);
  ResizeOnLargePages(order, n);
  if (key.Bits() + idBits <= 64)
  {
    OrderByPackedKeys(points, ids, key, idBits, order);
  }
  else
  {
    OrderByKeyedIds(points, ids, key, order);
  }
  return order;
}

} // namespace tessera
