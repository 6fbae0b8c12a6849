#include "areal_average.h"

#include "cache_line.h"
#include "dirichlet_tessellation.h"
#include "display_pieces.h"
#include "fan_diagonals.h"
#include "meridian_cut.h"
#include "errors.h"
#include "parallel_chunks.h"
#include "polygon_area.h"
#include "polygon_validation.h"
#include "shared_borders.h"
#include "snap_to_segments.h"
#include "spatial_order.h"
#include "tiles.h"
#include "window.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>

namespace tessera
{
namespace
{

constexpr std::int32_t NotInTessellation = -1;

/// The index of the lowest set bit of a nonzero word.
int LowestSetBit(std::uint64_t word)
{
#if defined(__GNUC__)
  return __builtin_ctzll(word);
#else
  int bit = 0;
  for (; (word & 1) == 0; word >>= 1)
  {
    ++bit;
  }
  return bit;
#endif
}

/// The number of set bits of a word.
int SetBitCount(std::uint64_t word)
{
#if defined(__GNUC__)
  return __builtin_popcountll(word);
#else
  int count = 0;
  for (; word != 0; word &= word - 1)
  {
    ++count;
  }
  return count;
#endif
}

/// The bytes [0, available) of bytes, at most 8, as a word (little-endian order, zeros above):
/// one 8-byte load when there are 8.
std::uint64_t BytesAt(const char* bytes, std::size_t available)
{
  std::uint64_t word = 0;
  if (available >= 8)
  {
    std::memcpy(&word, bytes, 8); // (a constant size: one load)
  }
  else
  {
    std::memcpy(&word, bytes, available);
  }
  return word;
}

/// Bits 0..count-1 (count <= 64) of the result: whether bytes[0..count-1] (each 0 or 1) are 1.
/// Eight bytes per multiplication: for bytes b_i of 0 or 1 at bits 8i, the product with this
/// constant holds b_i at bit 56 + i, as the one term 8i + 7j + 7 = 56 + i with i + j = 7; the
/// other terms take distinct bits, so nothing carries into the top byte.
std::uint64_t PackedBytes(const char* bytes, std::size_t count)
{
  constexpr std::uint64_t Gather = 0x0102040810204080ull;
  std::uint64_t word = 0;
  for (std::size_t k = 0; k < count; k += 8)
  {
    word |= ((BytesAt(bytes + k, count - k) * Gather) >> 56) << k;
  }
  return word;
}

/// Marks in wanted (one char per gauge) the gauges whose values are used at a step: those that
/// reported (a value that is not NaN), each the first of its place to report, in gauge order
/// (firstAtPlace: per gauge, the smallest gauge id at its place). taken is scratch. Returns their
/// number; sets infinite when some value is infinite (a reported value, marked as such).
int MarkFirstAtPlace(const std::vector<double>& values,
  const std::vector<std::int32_t>& firstAtPlace,
  char* wanted,
  std::vector<char>& taken,
  bool& infinite)
{
  const std::size_t n = values.size();
  taken.assign(n, 0);
  int used = 0;
  for (std::size_t g = 0; g < n; ++g)
  {
    infinite |= std::isinf(values[g]);
    char& placeTaken = taken[static_cast<std::size_t>(firstAtPlace[g])];
    wanted[g] = static_cast<char>(!std::isnan(values[g]) && !placeTaken);
    placeTaken |= wanted[g];
    used += wanted[g];
  }
  return used;
}

/// Words of 64 gauges in a gauge bitmap (gauge g is bit g % 64 of word g / 64).
std::size_t BitmapWords(std::size_t gauges)
{
  return (gauges + 63) / 64;
}

// Tiles derived locally (some 0.5 us each: they miss the cache) per thread, at least; as for
// ComputeTilesOf.
constexpr std::int64_t LocalTilesPerThread = 250;
/// Gauges whose values a thread of MarkReporting reads, at least (below that the pass stays on
/// the calling thread: it costs some 1-2 ns a gauge, a hand-off some microseconds).
constexpr std::int64_t MarksPerThread = 16384;
/// Words of the gauge bitmaps (16384 gauges) that Weigh sums in one block: its blocks' sums are
/// added in order, so the mean's bits depend on the number of gauges but not on the threads.
constexpr std::size_t WordsPerWeighBlock = 256;

/// Sorts values, each in [0, range), by marking them in a bitmap of the range and reading it back
/// (bits: all zero before and after): for the 2400 tiles changed at a step among 100k gauges,
/// some 1600 words read against a comparison sort's mispredicted branches (0.08 ms). Short lists,
/// and lists with a repeated value (which the bitmap would merge), are sorted by comparison.
void SortDistinctIntegers(std::vector<std::int32_t>& values,
  std::size_t range,
  std::vector<std::uint64_t>& bits)
{
  if (values.size() < 64)
  {
    std::sort(values.begin(), values.end());
    return;
  }
  if (bits.size() < range / 64 + 1)
  {
    bits.resize(range / 64 + 1, 0);
  }
  bool repeated = false;
  for (const std::int32_t value : values)
  {
    const std::uint64_t mask = std::uint64_t(1) << (value & 63);
    repeated |= (bits[value >> 6] & mask) != 0;
    bits[value >> 6] |= mask;
  }
  if (repeated)
  {
    for (const std::int32_t value : values)
    {
      bits[value >> 6] = 0;
    }
    std::sort(values.begin(), values.end());
    return;
  }
  std::size_t k = 0;
  for (std::size_t w = 0; k < values.size(); ++w)
  {
    for (std::uint64_t word = bits[w]; word != 0; word &= word - 1)
    {
      values[k++] = static_cast<std::int32_t>(64 * w + LowestSetBit(word));
    }
    bits[w] = 0;
  }
}

/// "gauge 7", or "gauge 7 (station 050848)" when the gauges have names.
std::string GaugeLabel(std::size_t gauge, const std::vector<std::string>& names)
{
  std::string label = "gauge " + std::to_string(gauge);
  if (gauge < names.size())
  {
    label += " (station " + names[gauge] + ")";
  }
  return label;
}

/// Throws InputError naming what (a setting, or an argument) unless step, metres between points
/// added along edges, is finite and at least MinGeodesicStepMetres: NaN, 0 or less turned the
/// densifying off without a word, and a step below a nanometre made a count of pieces no int holds.
void CheckStepMetres(double step, const char* what)
{
  if (!(step >= ArealAverageSettings::MinGeodesicStepMetres) || !std::isfinite(step))
  {
    throw InputError(std::string(what) + " must be a finite length of at least " +
      NumberText(ArealAverageSettings::MinGeodesicStepMetres) + " m, not " + NumberText(step));
  }
}

/// Padding, GeodesicStepMetres and CatchmentEdgeDegrees in their ranges (ArealAverageSettings),
/// each named (an edge step of NaN, 0 or less turned densifying off, and 1% of a 20-degree
/// catchment's area went without a word). A Padding of
/// 1e14 times the data's size left a window whose rounding swallowed the catchment's tiles (one
/// gauge of five weighted, the mean 5.0 for 3.0), a NaN one was named as a rectangle's NaN side,
/// and a negative one was taken as 0.01; a GeodesicStepMetres of 0.001 ran out of memory, and a
/// NaN, zero or negative one turned the densification off.
void CheckSettingsRange(const ArealAverageSettings& settings)
{
  if (!(settings.Padding >= 0.0 && settings.Padding <= ArealAverageSettings::MaxPadding))
  {
    throw InputError("Padding must be a fraction from 0 to " +
      NumberText(ArealAverageSettings::MaxPadding) + " of the data's larger side, not " +
      NumberText(settings.Padding));
  }
  CheckStepMetres(settings.GeodesicStepMetres, "GeodesicStepMetres");
  if (!(settings.CatchmentEdgeDegrees > 0.0) || !std::isfinite(settings.CatchmentEdgeDegrees))
  {
    throw InputError("CatchmentEdgeDegrees must be a finite angle above 0, not " +
      NumberText(settings.CatchmentEdgeDegrees));
  }
}

} // namespace

struct ThiessenArealAverage::State
{
  // The constructor's stages, in order (after the inputs are checked); MakeWindow calls
  // PrepareUpdates when updating.
  void ChooseProjection(const CleanRings& rings);
  void PlaceGauges(const std::vector<Point2>& gaugesLonLat);
  void ProjectCatchment(const CleanRings& rings);
  void MakeWindow();
  void PrepareUpdates(double clearMargin);

  // A step's stages (Step): the tessellation updated (ApplyReportedChanges) or rebuilt, then the
  // tiles derived, then the weights.
  struct Changes
  {
    bool Local = false; ///< only the touched and inserted gauges' tiles need deriving
    std::vector<std::int32_t> Inserted, Touched;
    std::size_t Deferred = 0; ///< removals deferred (DeferClearRemovals)
  };
  Changes ApplyReportedChanges();
  void RebuildFromWanted();
  void Weigh(const std::vector<double>& values, ArealStep& step) const;
  std::vector<std::size_t> WeighBlockStarts() const;
  std::pair<double, double> WeighBlock(std::size_t block,
    std::size_t first,
    const std::vector<double>& values,
    ArealStep& step) const;

  ArealAverageSettings Settings;
  ProjectionParameters Parameters;
  std::unique_ptr<GeographicProjection> Projector;
  AreaMethod Method = AreaMethod::EqualAreaPlane;

  std::vector<Point2> GaugesXY;
  std::vector<std::int32_t> FirstAtPlace; // per gauge: smallest gauge id at its coordinates
  std::vector<char> PlaceShared;          // per gauge: others share its place (empty when none do)

  bool SharesPlace(std::int32_t g) const
  {
    return !this->PlaceShared.empty() && this->PlaceShared[g];
  }
  std::vector<std::pair<std::int32_t, std::int32_t>> Duplicates;
  std::size_t SnappedVertices = 0; // catchment vertices put onto other rings' edges

  std::unique_ptr<Catchment> Region;
  double CatchmentArea = 0.0;
  std::unique_ptr<Window> TheWindow;

  std::unique_ptr<DirichletTessellation> Tessellation;
  std::vector<std::int32_t> EngineOfGauge; // engine id, or NotInTessellation
  // Per gauge (updates only): its engine id while it is removed, -1 if never inserted. A gauge
  // that reports again is inserted under its old id (Reinsert): the first step inserts the
  // gauges along the Hilbert curve, so ids near in space are near in memory, and they stay so
  // (new ids at each step, as Insert gives them, left the points of a tile's ring spread over
  // the coordinates and vertex arrays).
  std::vector<std::int32_t> RemovedId;
  std::vector<std::int32_t> GaugeOfEngine;
  std::vector<std::int32_t> CurveOrder; // every gauge, along the Hilbert curve (updates only)
  std::vector<std::int32_t> CurveRank;  // per gauge, its position in CurveOrder
  std::vector<std::uint64_t> SortBits;  // SortDistinctIntegers' bitmap, all zero between uses

  // Per gauge: the clipped area (m^2) of its tile, as last derived.
  std::vector<double> CachedArea;
  // Per engine id of a gauge in the tessellation (updates only): a box holding its tile, the
  // tile's own box when it was last derived, grown since by the removals next to it; for a gauge
  // inserted and not derived since, the joined boxes of its neighbours at its insertion (Apply).
  // By engine id, not gauge: Apply reads and grows the boxes of each changed gauge's neighbours,
  // whose ids are near each other (RemovedId), where their gauge numbers are anywhere.
  std::vector<Box2> TileBounds;
  // How far clear of the catchment's box a box must be (a millionth of the window's larger side,
  // about 1 m in Colorado): the boxes are those of computed tiles, whose vertices are rounded
  // (by some 1e-10 m there), so a tile derived again could poke out by its rounding. Only a face
  // centre far outside its rounding's usual size (from a nearly collinear triple) could exceed the
  // margin, and then the derived tile itself is off by as much.
  double ClearMargin = 0.0;
  std::vector<std::int32_t> Neighbours;  // Apply's scratch
  std::vector<std::int32_t> PrefetchIds; // PrefetchForRemovals' and PrefetchForInsertions'
  /// What clipping and measuring a tile needs besides the tile: one per thread of a clipping pass,
  /// written at every tile by that thread, on cache lines of its own (cache_line.h).
  struct alignas(CacheLineBytes) ClipScratch
  {
    Catchment::Workspace Work;
    ClippedRings Rings;
    std::vector<Point2> Dense;
    std::vector<Point2> LonLat;
    // PositiveArea's changes from this thread's tiles: g where the area is positive, ~g where
    // not (ApplyPositiveAreas).
    std::vector<std::int32_t> PositiveMarks;
  };
  std::vector<ClipScratch> Scratch{ 1 }; // [0]: the calling thread's
  LocalTilesWorkspace LocalTiles;        // DeriveChanged's, kept between steps
  std::vector<char> Wanted; // per gauge: used this step (kept: a step is O(gauges) already)
  // Per engine id (updates only): 1 while its gauge is in the tessellation though not used, its
  // removal deferred because its tile is clear of the catchment (DeferClearRemovals). Its clipped
  // area is 0, and stays 0 for as long as it is deferred. By engine id, as TileBounds: Apply and
  // DeriveChanged read it for the neighbours of the changed gauges.
  std::vector<char> Deferred;
  // Per gauge (updates only): 1 while it is in the tessellation and not deferred, i.e. used at
  // the last step (ListChanges compares the reporting gauges with it).
  std::vector<char> Used;
  std::vector<char> PlaceTaken;
  std::vector<char> Marked; // DeriveChanged's, per engine id
  // Wanted and CachedArea > 0 as bitmaps (BitmapWords), so that a step finds its weighted gauges
  // by reading two bits per gauge instead of a byte and a double: at 100k gauges that pass read
  // 0.9 MB and took a twentieth of an update. The clipping threads note PositiveArea's bits as
  // they store the areas, and the bits are set after their pass (NotePositiveArea,
  // ApplyPositiveAreas).
  std::vector<std::uint64_t> WantedBits;
  std::vector<std::uint64_t> PositiveArea;
  // When updating, the gauges whose Wanted differs from Used, ascending (MarkReporting): a
  // step's changes, found while marking.
  std::vector<std::int32_t> ChangedGauges;
  /// MarkWords' results for its words, joined in order by MarkReporting.
  struct MarkPart
  {
    std::vector<std::int32_t> Changed;
    int Used = 0;
    bool Infinite = false;
  };
  std::vector<OwnCacheLines<MarkPart>> MarkParts; // MarkReporting's, per chunk (kept: reused)

  void ClearArea(std::int32_t g)
  {
    this->CachedArea[g] = 0.0;
    this->SetPositiveArea(g, false);
  }

  /// Gauge g's bit of PositiveArea.
  void SetPositiveArea(std::int32_t g, bool positive)
  {
    const std::uint64_t bit = std::uint64_t(1) << (g & 63);
    std::uint64_t& word = this->PositiveArea[g >> 6];
    word = positive ? word | bit : word & ~bit;
  }

  /// Gauge g's bit of PositiveArea to be set as its new area is positive or not, noted by a
  /// clipping thread in its scratch: threads store the areas of gauges whose bits share a word, and
  /// an atomic update of the bit there drained the thread's pending stores (the area's, at a
  /// random place in 0.8 MB) at every tile. A serial pass after the clipping, reading each stored
  /// area back, took some 25 us of a 100k-gauge update; the notes are read from where they were
  /// just written.
  static void NotePositiveArea(std::int32_t g, double area, ClipScratch& scratch)
  {
    scratch.PositiveMarks.push_back(area > 0.0 ? g : ~g);
  }

  /// PositiveArea's bits as the first `chunks` scratches noted them, and the notes cleared. (A
  /// gauge is noted by one thread at most in a pass: each tile is clipped once.)
  void ApplyPositiveAreas(std::size_t chunks)
  {
    for (std::size_t c = 0; c < chunks; ++c)
    {
      for (const std::int32_t mark : this->Scratch[c].PositiveMarks)
      {
        this->SetPositiveArea(mark >= 0 ? mark : ~mark, mark >= 0);
      }
      this->Scratch[c].PositiveMarks.clear();
    }
  }

  /// Wanted[g] = 1 for the gauges used at this step: those that reported, the first of each
  /// place, also as WantedBits, and when updating the gauges whose use changes (ChangedGauges).
  /// Returns their number; throws InputError naming a gauge with an infinite value.
  int MarkReporting(const std::vector<double>& values)
  {
    const std::size_t n = values.size();
    this->Wanted.resize(n);
    this->WantedBits.resize(BitmapWords(n));
    this->ChangedGauges.clear();
    if (!this->Duplicates.empty())
    {
      const int used = this->MarkReportingGrouped(values);
      for (std::size_t w = 0; w < BitmapWords(n); ++w)
      {
        this->CompleteWord(w, this->ChangedGauges);
      }
      return used;
    }
    return this->MarkInChunks(values);
  }

  /// MarkReporting without duplicates, in chunks of words on the cores (MarkWords), their results
  /// joined in order: the pass reads every value, 0.8 MB at 100k gauges, fresh from memory at
  /// each step, and one core alone waited on it for a tenth of an update.
  int MarkInChunks(const std::vector<double>& values)
  {
    const std::size_t n = values.size();
    const std::vector<std::int32_t> bounds =
      parallel::ChunkBounds(static_cast<std::int32_t>(BitmapWords(n)),
        parallel::ThreadCount(static_cast<std::int64_t>(n), MarksPerThread));
    const std::size_t chunks = bounds.size() - 1;
    if (this->MarkParts.size() < chunks)
    {
      this->MarkParts.resize(chunks);
    }
    parallel::RunChunks(chunks,
      [&](std::size_t k)
      { this->MarkWords(values.data(), bounds[k], bounds[k + 1], this->MarkParts[k].Value); });
    int used = 0;
    bool infinite = false;
    for (std::size_t k = 0; k < chunks; ++k)
    {
      const MarkPart& part = this->MarkParts[k].Value;
      used += part.Used;
      infinite |= part.Infinite;
      this->ChangedGauges.insert(
        this->ChangedGauges.end(), part.Changed.begin(), part.Changed.end());
    }
    if (infinite)
    {
      ThrowAtFirstInfinite(values);
    }
    return used;
  }

  /// MarkReporting's words [begin, end) (gauges 64 begin .. 64 end - 1), without duplicates.
  void MarkWords(const double* value, std::size_t begin, std::size_t end, MarkPart& part)
  {
    // Without branches on the values: in a real record, which gauges report is close to random,
    // and a mispredicted branch per gauge was most of this loop's time. Through local pointers: a
    // char store may alias anything, so wanted[g] made the compiler reload the vectors' data
    // pointers at every gauge (a fifth of a 100k-gauge step's own time went to this loop).
    // Sixty-four gauges at a time, each word completed while its marks are in the cache.
    const std::size_t n = this->Wanted.size();
    char* const mark = this->Wanted.data();
    int used = 0;
    bool infinite = false;
    part.Changed.clear();
    for (std::size_t w = begin; w < end; ++w)
    {
      for (std::size_t g = 64 * w; g < std::min(n, 64 * w + 64); ++g)
      {
        const bool reported = !std::isnan(value[g]);
        infinite |= std::isinf(value[g]);
        mark[g] = static_cast<char>(reported);
        used += reported;
      }
      this->CompleteWord(w, part.Changed);
    }
    part.Used = used;
    part.Infinite = infinite;
  }

  /// Packs word w's marks (gauges 64w..64w+63) into WantedBits and, when updating, appends those
  /// of its gauges whose Wanted and Used differ to changed. Eight gauges per comparison (both
  /// hold 0 or 1): few change at a step, so most eights are equal and skipped. (A branch per
  /// gauge on its presence, mispredicted for a third of them, was most of the time of listing
  /// changes once: 0.4 of 0.45 ms per step among 100k gauges. A second pass over both arrays to
  /// list them took a twentieth of an update.)
  void CompleteWord(std::size_t w, std::vector<std::int32_t>& changed)
  {
    const std::size_t first = 64 * w, end = std::min(this->Wanted.size(), first + 64);
    const char* const now = this->Wanted.data();
    this->WantedBits[w] = PackedBytes(now + first, end - first);
    if (!this->Settings.Incremental)
    {
      return;
    }
    const char* const before = this->Used.data();
    for (std::size_t g = first; g < end; g += 8)
    {
      const std::uint64_t differs = BytesAt(now + g, end - g) ^ BytesAt(before + g, end - g);
      for (std::uint64_t differ = differs; differ != 0; differ &= differ - 1)
      {
        changed.push_back(static_cast<std::int32_t>(g + LowestSetBit(differ) / 8));
      }
    }
  }

  int MarkReportingGrouped(const std::vector<double>& values)
  {
    bool infinite = false;
    const int used =
      MarkFirstAtPlace(values, this->FirstAtPlace, this->Wanted.data(), this->PlaceTaken, infinite);
    if (infinite)
    {
      ThrowAtFirstInfinite(values);
    }
    return used;
  }

  [[noreturn]] void ThrowAtFirstInfinite(const std::vector<double>& values) const
  {
    const auto first =
      std::find_if(values.begin(), values.end(), [](double value) { return std::isinf(value); });
    throw InputError(
      GaugeLabel(static_cast<std::size_t>(first - values.begin()), this->Settings.GaugeNames) +
      " has an infinite value");
  }

  /// The plane's points in lon/lat (points of the catchment's clipped tiles: within the image of
  /// the catchment, so each has its place).
  void Unproject(const std::vector<Point2>& plane, std::vector<Point2>& lonlat) const
  {
    lonlat.resize(plane.size());
    for (std::size_t i = 0; i < plane.size(); ++i)
    {
      lonlat[i] = this->Projector->InverseOfImage(plane[i]);
    }
  }

  /// Ellipsoidal area (m^2) of one ring in the plane: densified, unprojected, measured.
  double MeasureRing(const Point2* ring, std::size_t count, ClipScratch& scratch) const
  {
    if (count < 3)
    {
      return 0.0;
    }
    DensifyRingSymmetrically(ring, count, this->Settings.GeodesicStepMetres, scratch.Dense);
    this->Unproject(scratch.Dense, scratch.LonLat);
    return EllipsoidalRingArea(scratch.LonLat);
  }

  /// Ellipsoidal area (m^2) of all the rings.
  double MeasureRings(const ClippedRings& rings, ClipScratch& scratch) const
  {
    double total = 0.0;
    for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
    {
      const std::size_t begin = rings.RingOffsets[r];
      total += this->MeasureRing(&rings.Vertices[begin], rings.RingOffsets[r + 1] - begin, scratch);
    }
    return total;
  }

  /// Ellipsoidal area (m^2) of a simple anticlockwise polygon in the plane, measured as the tiles
  /// are.
  double PieceArea(const Point2* piece, std::size_t count, ClipScratch& scratch) const
  {
    return this->Method == AreaMethod::EqualAreaPlane ? CompensatedPolygonArea(piece, count)
                                                      : this->MeasureRing(piece, count, scratch);
  }

  // CurrentClippedTiles' parts: read only, with the caller's own scratch.

  /// The used gauges' tiles clipped by the catchment, as display pieces in the plane, in out's
  /// order (their gauges, areas and TilePieceOffsets appended to out). The tiles are clipped and
  /// cut on the cores, each in a thread's scratch (scratch: one per chunk), and joined in gauge
  /// order: the same pieces on any number of threads.
  ClippedRings PlanePiecesOfUsedTiles(std::vector<ClipScratch>& scratch,
    ClippedTilesLonLat& out) const
  {
    // The gauges in the tessellation, ascending, with their tiles (derived again here: the steps
    // keep only the clipped areas).
    const TileSet tiles = TessellationDual(*this->Tessellation).Tiles();
    std::vector<std::int32_t> tileOf(this->EngineOfGauge.size(), -1);
    for (std::size_t k = 0; k < tiles.PointIds.size(); ++k)
    {
      tileOf[this->GaugeOfEngine[tiles.PointIds[k]]] = static_cast<std::int32_t>(k);
    }
    // The used gauges with tiles (a gauge in the tessellation but not used: its removal is
    // deferred).
    std::vector<std::int32_t> used;
    for (std::size_t gauge = 0; gauge < tileOf.size(); ++gauge)
    {
      if (tileOf[gauge] >= 0 && this->Wanted[gauge])
      {
        used.push_back(static_cast<std::int32_t>(gauge));
      }
    }
    std::vector<TilePieces> parts(used.size());
    parallel::RunClaimed(used.size(),
      std::min(scratch.size(), parallel::ThreadCount(std::int64_t(used.size()), 16)),
      [&](std::size_t i, std::size_t chunk)
      {
        const std::size_t k = static_cast<std::size_t>(tileOf[used[i]]);
        parts[i] = this->PlanePiecesOf(&tiles.Vertices[tiles.Offsets[k]],
          static_cast<std::size_t>(tiles.Offsets[k + 1] - tiles.Offsets[k]),
          static_cast<std::size_t>(used[i]),
          scratch[chunk]);
      });
    ClippedRings plane; // the pieces in the plane, in out's order
    for (std::size_t i = 0; i < used.size(); ++i)
    {
      AppendTilePieces(used[i], parts[i], plane, out);
    }
    return plane;
  }

  /// A clipped tile's display pieces in the plane and their areas.
  struct TilePieces
  {
    ClippedRings Pieces;
    std::vector<double> Areas;
  };

  /// Gauge g's tile clipped and cut into display pieces (none when the clip is empty or has no
  /// area), each measured.
  TilePieces PlanePiecesOf(const Point2* tile,
    std::size_t count,
    std::size_t g,
    ClipScratch& scratch) const
  {
    TilePieces made;
    ClippedRings rings;
    if (this->Region->ClipInto(
          tile, count, g, scratch.Work, &rings, Catchment::FoldedTile::IsEmpty) <= 0.0)
    {
      return made;
    }
    made.Pieces = DisplayPieces(rings);
    for (std::size_t r = 0; r + 1 < made.Pieces.RingOffsets.size(); ++r)
    {
      const std::size_t begin = made.Pieces.RingOffsets[r];
      made.Areas.push_back(this->PieceArea(
        &made.Pieces.Vertices[begin], made.Pieces.RingOffsets[r + 1] - begin, scratch));
    }
    return made;
  }

  /// Appends gauge g's pieces to plane, their areas and g to out; nothing when it has none.
  static void AppendTilePieces(std::int32_t g,
    const TilePieces& tile,
    ClippedRings& plane,
    ClippedTilesLonLat& out)
  {
    if (tile.Areas.empty())
    {
      return; // (an empty clip, or only rings of no area)
    }
    out.Gauges.push_back(g);
    for (std::size_t r = 0; r < tile.Areas.size(); ++r)
    {
      const Point2* piece = &tile.Pieces.Vertices[tile.Pieces.RingOffsets[r]];
      const std::size_t size = tile.Pieces.RingOffsets[r + 1] - tile.Pieces.RingOffsets[r];
      out.PieceAreasM2.push_back(tile.Areas[r]);
      plane.Vertices.insert(plane.Vertices.end(), piece, piece + size);
      plane.RingOffsets.push_back(plane.Vertices.size());
    }
    out.TilePieceOffsets.push_back(plane.RingOffsets.size() - 1);
  }

  /// The pieces in the plane (shared: their borders' vertices shared) in lon/lat, their edges
  /// densified every maxStepMetres in the plane; fans gets, per piece, whether it is a fan about
  /// its first vertex in lon/lat. On the cores, a piece at a time (scratch: one per chunk).
  ClippedRings PiecesInLonLat(const ClippedRings& shared,
    double maxStepMetres,
    std::vector<ClipScratch>& scratch,
    std::vector<char>& fans) const
  {
    const std::size_t count = shared.RingOffsets.size() - 1;
    std::vector<std::vector<Point2>> pieces(count);
    fans.assign(count, 0);
    parallel::RunClaimed(count,
      std::min(scratch.size(), parallel::ThreadCount(std::int64_t(count), 64)),
      [&](std::size_t r, std::size_t chunk)
      {
        ClipScratch& own = scratch[chunk];
        const std::size_t begin = shared.RingOffsets[r];
        DensifyRingSymmetrically(
          &shared.Vertices[begin], shared.RingOffsets[r + 1] - begin, maxStepMetres, own.Dense);
        this->Unproject(own.Dense, pieces[r]);
        SnapToMeridian(pieces[r]);       // (a border along it stays on it, not an ulp either side)
        DropRepeatedVertices(pieces[r]); // points an ulp apart in the plane can come back as one
        // The plane's fan (display_pieces.h) about its first vertex, bent: a side bowing inwards
        // in lon/lat left slivers drawn twice (0.5% of a Colorado tile's area).
        fans[r] = StartAtFanApex(pieces[r]);
      });
    ClippedRings lonLat; // the pieces in lon/lat, as cut in the plane
    for (const std::vector<Point2>& piece : pieces)
    {
      lonLat.Vertices.insert(lonLat.Vertices.end(), piece.begin(), piece.end());
      lonLat.RingOffsets.push_back(lonLat.Vertices.size());
    }
    return lonLat;
  }

  /// out's display pieces from the pieces in lon/lat (lonLat, out.TilePieceOffsets's and
  /// out.PieceAreasM2's): a piece that is no fan about its first vertex there (fans[r] 0: bent,
  /// no vertex of it sees it whole) split along diagonals into fans (fan_diagonals.h), each part
  /// measured as the pieces are, in the plane (its vertices projected back), the parts' areas
  /// scaled to sum to the piece's.
  void SetDisplayPieces(const ClippedRings& lonLat,
    const std::vector<char>& fans,
    ClipScratch& scratch,
    ClippedTilesLonLat& out) const
  {
    const std::vector<double> areas = std::move(out.PieceAreasM2);
    const std::vector<std::size_t> offsets = std::move(out.TilePieceOffsets);
    out.PieceAreasM2.clear();
    out.TilePieceOffsets.assign(1, 0);
    out.Pieces = ClippedRings();
    const auto append = [&out](const Point2* ring, std::size_t count, double area)
    {
      out.Pieces.Vertices.insert(out.Pieces.Vertices.end(), ring, ring + count);
      out.Pieces.RingOffsets.push_back(out.Pieces.Vertices.size());
      out.PieceAreasM2.push_back(area);
    };
    for (std::size_t k = 0; k + 1 < offsets.size(); ++k)
    {
      for (std::size_t r = offsets[k]; r < offsets[k + 1]; ++r)
      {
        const Point2* ring = &lonLat.Vertices[lonLat.RingOffsets[r]];
        const std::size_t count = lonLat.RingOffsets[r + 1] - lonLat.RingOffsets[r];
        const std::vector<std::vector<Point2>> parts =
          fans[r] ? std::vector<std::vector<Point2>>() : FansByDiagonals({ ring, ring + count });
        if (parts.size() < 2)
        {
          append(ring, count, areas[r]);
          continue;
        }
        // Each part measured in the plane, its vertices projected back, and the parts' areas
        // scaled to the piece's own, as the weights measured it: the geodesic measure densifies
        // the parts' edges from other points, and a tile's parts summed to 1.2e-7 off its area.
        std::vector<double> partAreas;
        for (const std::vector<Point2>& part : parts)
        {
          std::vector<Point2> inPlane(part.size());
          for (std::size_t v = 0; v < part.size(); ++v)
          {
            inPlane[v] = this->Projector->Forward(part[v]);
          }
          partAreas.push_back(this->PieceArea(inPlane.data(), inPlane.size(), scratch));
        }
        const double sum = std::accumulate(partAreas.begin(), partAreas.end(), 0.0);
        for (std::size_t p = 0; p < parts.size(); ++p)
        {
          const double share =
            sum > 0.0 ? partAreas[p] / sum : 1.0 / static_cast<double>(parts.size());
          append(parts[p].data(), parts[p].size(), areas[r] * share);
        }
      }
      out.TilePieceOffsets.push_back(out.PieceAreasM2.size());
    }
  }

  /// Ellipsoidal area (m^2) of tile & catchment. (A tile between gauges some nanometres apart,
  /// closer than CoLocatedMetres allows by default, can come out folded: it counts as empty.)
  double ClippedArea(const Point2* tile,
    std::size_t count,
    std::size_t tileId,
    ClipScratch& scratch) const
  {
    if (this->Method == AreaMethod::EqualAreaPlane)
    {
      return this->Region->ClipInto(
        tile, count, tileId, scratch.Work, nullptr, Catchment::FoldedTile::IsEmpty);
    }
    scratch.Rings.RingOffsets.assign(1, 0);
    scratch.Rings.Vertices.clear();
    const double planar = this->Region->ClipInto(
      tile, count, tileId, scratch.Work, &scratch.Rings, Catchment::FoldedTile::IsEmpty);
    if (planar <= 0.0)
    {
      return 0.0;
    }
    return this->MeasureRings(scratch.Rings, scratch);
  }

  void Rebuild(const std::vector<std::int32_t>& active)
  {
    std::vector<Point2> points;
    points.reserve(active.size());
    std::fill(this->EngineOfGauge.begin(), this->EngineOfGauge.end(), NotInTessellation);
    this->GaugeOfEngine.clear();
    for (std::int32_t g : active)
    {
      this->EngineOfGauge[g] = static_cast<std::int32_t>(points.size());
      this->GaugeOfEngine.push_back(g);
      points.push_back(this->GaugesXY[g]);
    }
    this->Tessellation.reset(new DirichletTessellation(*this->TheWindow, std::move(points)));
  }

  /// Gauges in Hilbert order over the window. The engine's walks (to the point to remove, to the
  /// triangle holding the point to insert) start where the previous operation ended, as Green and
  /// Sibson's walk from the last point does, so a spatially random order would cost O(sqrt n) per
  /// operation.
  void SpatialSort(std::vector<std::int32_t>& gauges) const
  {
    const std::vector<Point2>& corners = this->TheWindow->Vertices();
    SortAlongHilbertCurve(this->GaugesXY.data(), BoundsOf(corners.data(), corners.size()), gauges);
  }

  /// The same order for a few gauges, from their ranks along the curve (updates only): sorting
  /// integers instead of computing Hilbert keys took a third of the time of listing changes.
  void SortAlongCurve(std::vector<std::int32_t>& gauges)
  {
    for (std::int32_t& g : gauges)
    {
      g = this->CurveRank[g];
    }
    SortDistinctIntegers(gauges, this->CurveOrder.size(), this->SortBits);
    for (std::int32_t& rank : gauges)
    {
      rank = this->CurveOrder[rank];
    }
  }

  /// The gauges that stopped reporting and those that started, each list in Hilbert order, from
  /// the changes MarkReporting found. A gauge whose removal was deferred and that reports again is
  /// neither: it is used as it is.
  void ListChanges(const std::vector<char>& wanted,
    std::vector<std::int32_t>& removed,
    std::vector<std::int32_t>& inserted)
  {
    removed.clear();
    inserted.clear();
    for (const std::int32_t g : this->ChangedGauges)
    {
      this->ListChange(wanted, static_cast<std::size_t>(g), removed, inserted);
    }
    this->SortAlongCurve(removed);
    this->SortAlongCurve(inserted);
  }

  void ListChange(const std::vector<char>& wanted,
    std::size_t g,
    std::vector<std::int32_t>& removed,
    std::vector<std::int32_t>& inserted)
  {
    if (wanted[g] == this->Used[g])
    {
      return;
    }
    if (!wanted[g])
    {
      removed.push_back(static_cast<std::int32_t>(g));
    }
    else if (this->EngineOfGauge[g] == NotInTessellation)
    {
      inserted.push_back(static_cast<std::int32_t>(g));
    }
    else
    {
      // Deferred: its tile is still clear of the catchment (area 0, as cached).
      this->Deferred[this->EngineOfGauge[g]] = 0;
      this->Used[g] = 1;
    }
  }

  /// Defers the removals (from removed) of gauges whose tiles are clear of the catchment: they
  /// stay in the tessellation, unused, and removed keeps the others. Returns how many.
  ///
  /// Why the result is unchanged. A point of the catchment lies in the tile of a gauge that is
  /// not deferred (deferred tiles are clear of it), and no gauge used at this step is nearer to
  /// it than that one, since the used gauges are those of the tessellation less the deferred
  /// ones (the insertions of the step come next, as usual). So every used gauge's tile has the
  /// same part of the catchment as in the tessellation of the used gauges alone. A deferred tile
  /// grows only when a neighbour is removed (Apply grows its box then, and removes it for real
  /// once the box reaches the catchment), and shrinks when one is inserted.
  ///
  ///      catchment          gauges far outside (x: stopped reporting, removal deferred)
  ///     +---------+
  ///     |  a   b  |    c     x      x     the tiles of c and x change only outside the
  ///     +---------+         d             catchment when x goes: nothing used changes
  ///
  /// A gauge that shares its place with others is never deferred: another of them may report
  /// while it stays in the tessellation, and two gauges at one place cannot both be vertices (an
  /// exact copy would be the engine's duplicate, without a tile of its own).
  std::size_t DeferClearRemovals(std::vector<std::int32_t>& removed)
  {
    const auto kept = std::stable_partition(removed.begin(),
      removed.end(),
      [this](std::int32_t g)
      { return this->SharesPlace(g) || !this->ClearOfCatchment(this->BoundsOfGauge(g)); });
    for (auto it = kept; it != removed.end(); ++it)
    {
      this->Deferred[this->EngineOfGauge[*it]] = 1;
      this->Used[*it] = 0;
      this->ClearArea(*it);
    }
    const std::size_t deferred = static_cast<std::size_t>(removed.end() - kept);
    removed.erase(kept, removed.end());
    return deferred;
  }

  /// Every deferred gauge, for removal with the rest (a step that derives every tile keeps no
  /// deferred gauge: their tiles are not watched then).
  void TakeAllDeferred(std::vector<std::int32_t>& removed)
  {
    for (std::size_t id = 0; id < this->Deferred.size(); ++id)
    {
      if (this->Deferred[id])
      {
        this->Deferred[id] = 0;
        removed.push_back(this->GaugeOfEngine[id]);
      }
    }
    this->SortAlongCurve(removed);
  }

  /// The engine id of a gauge in the tessellation next to gauge g along the Hilbert curve (a few
  /// steps either way), where the walk to g starts: the gauges inserted at one step are spread
  /// over the whole window, and a walk from the one before crossed some ten triangles, a cache
  /// miss each. -1 when none is near on the curve (the walk then starts where the last ended).
  std::int32_t PresentNear(std::int32_t g) const
  {
    const std::int64_t rank = this->CurveRank[g];
    const std::int64_t n = static_cast<std::int64_t>(this->CurveOrder.size());
    for (std::int64_t step = 1; step <= 8; ++step)
    {
      for (const std::int64_t q : { rank - step, rank + step })
      {
        if (q >= 0 && q < n)
        {
          const std::int32_t id = this->EngineOfGauge[this->CurveOrder[q]];
          if (id != NotInTessellation)
          {
            return id;
          }
        }
      }
    }
    return -1;
  }

  /// Removes, then inserts (Green-Sibson removal and insertion). With touched, also lists the
  /// gauges whose tiles' areas may change, and grows the tile boxes: a tile gains or loses area
  /// only when a point joined to it by a triangulation edge is removed or inserted
  /// (DirichletTessellation::AppendNeighbours), so the neighbours of each removed gauge just
  /// before its removal, and of each inserted gauge just after its insertion, are all of them.
  /// (Face mates taken once for the whole step, as the full derivation defines them, cost more:
  /// they need the faces labelled.) A removed gauge's tile goes to its neighbours, so each of
  /// their boxes takes in its box; an insertion only shrinks tiles, and the inserted gauge's tile
  /// is made of pieces of its neighbours' tiles, so its box is their joined boxes:
  ///
  ///        before          remove r            r's neighbours' boxes take in r's box
  ///     +---+---+---+    +---+-------+
  ///     | a | r | b |    | a :   b   |         (a's new tile lies in its box + r's box)
  ///     +---+---+---+    +---+-------+
  ///
  ///        before          insert i            i's box joins a's and b's boxes
  ///     +-----+-----+    +---+---+---+
  ///     |  a  :  b  |    | a | i | b |         (i's tile lies in a's and b's old tiles)
  ///     +-----+-----+    +---+---+---+
  ///
  /// (The same walk argument as AppendNeighbours': a piece of an old tile j inside i's new tile is
  /// open, so j and i share an edge of positive length, and j is among i's neighbours.)
  ///
  /// Returns false when the tessellation stopped being two-dimensional on the way (a removal that
  /// leaves the points collinear rebuilds it): then the list (if one was asked for) is incomplete
  /// and every tile must be derived.
  bool Apply(const std::vector<std::int32_t>& removed,
    const std::vector<std::int32_t>& inserted,
    std::vector<std::int32_t>* touched)
  {
    const bool local = touched != nullptr; // (a step that is not has no deferred gauge)
    this->PrefetchForRemovals(removed);
    for (const std::int32_t g : removed)
    {
      this->RemoveGauge(g, touched);
    }
    this->RemoveDeferredThatGrew(touched);
    if (local && !touched)
    {
      // The tessellation stopped being two-dimensional on the way, so every tile is derived: no
      // gauge stays deferred (its tile may reach the catchment now).
      std::vector<std::int32_t> rest;
      this->TakeAllDeferred(rest);
      for (const std::int32_t g : rest)
      {
        this->RemoveGauge(g, touched);
      }
    }
    this->PrefetchForInsertions(inserted);
    for (const std::int32_t g : inserted)
    {
      this->InsertGauge(g, touched);
    }
    return touched != nullptr;
  }

  // Apply's operations lie apart in memory (a few hundred among 100k gauges, and their gauge
  // numbers anywhere), so each began by waiting for cache misses of its own, one operation after
  // the other: its gauge's entries, then its vertex, then that vertex's triangle. These passes ask
  // for all of them first, a level at a time, so that the misses of a level overlap (they took a
  // tenth off the removals and insertions of the synthetic 100k-gauge stream). They read only,
  // and ask for nothing when more than PrefetchedOperations operations are listed: those of the
  // first step, or of a step that changes many gauges, would leave the cache before their turn.

  static constexpr std::size_t PrefetchedOperations = 8192;

  /// The per-gauge entries that a removal or an insertion of each gauge reads first.
  void PrefetchGaugeEntries(const std::vector<std::int32_t>& gauges) const
  {
    for (const std::int32_t g : gauges)
    {
      __builtin_prefetch(&this->EngineOfGauge[g]);
      __builtin_prefetch(&this->RemovedId[g]);
      __builtin_prefetch(&this->CurveRank[g]);
      __builtin_prefetch(&this->Used[g]);
    }
  }

  /// For removals: the gauges' entries, then their vertices' boxes, points and triangles.
  void PrefetchForRemovals(const std::vector<std::int32_t>& removed)
  {
    if (removed.size() > PrefetchedOperations)
    {
      return;
    }
    this->PrefetchGaugeEntries(removed);
    std::vector<std::int32_t>& ids = this->PrefetchIds;
    ids.clear();
    for (const std::int32_t g : removed)
    {
      ids.push_back(this->EngineOfGauge[g]);
      __builtin_prefetch(&this->TileBounds[ids.back()]);
    }
    this->Tessellation->Prefetch(ids.data(), ids.size());
  }

  /// For insertions: the gauges' entries and their old ids' points, then their neighbours along
  /// the curve (PresentNear), then the vertices where their walks start.
  void PrefetchForInsertions(const std::vector<std::int32_t>& inserted)
  {
    if (inserted.size() > PrefetchedOperations)
    {
      return;
    }
    const std::int64_t last = static_cast<std::int64_t>(this->CurveOrder.size()) - 1;
    const auto before = [](std::int64_t rank) { return std::max<std::int64_t>(0, rank - 1); };
    const auto after = [last](std::int64_t rank) { return std::min(last, rank + 1); };
    this->PrefetchGaugeEntries(inserted);
    std::vector<std::int32_t>& ids = this->PrefetchIds;
    ids.clear();
    for (const std::int32_t g : inserted)
    {
      const std::int64_t rank = this->CurveRank[g];
      __builtin_prefetch(&this->CurveOrder[before(rank)]);
      __builtin_prefetch(&this->CurveOrder[after(rank)]);
      ids.push_back(this->RemovedId[g]);
    }
    this->Tessellation->Prefetch(ids.data(), ids.size());
    for (const std::int32_t g : inserted)
    {
      const std::int64_t rank = this->CurveRank[g];
      __builtin_prefetch(&this->EngineOfGauge[this->CurveOrder[before(rank)]]);
      __builtin_prefetch(&this->EngineOfGauge[this->CurveOrder[after(rank)]]);
    }
    ids.clear();
    for (const std::int32_t g : inserted)
    {
      ids.push_back(this->PresentNear(g));
    }
    this->Tessellation->Prefetch(ids.data(), ids.size());
  }

  /// Apply's removal of gauge g: its neighbours touched (when listed) and their boxes grown by
  /// its box; touched becomes null when the tessellation stops being two-dimensional.
  void RemoveGauge(std::int32_t g, std::vector<std::int32_t>*& touched)
  {
    DirichletTessellation& t = *this->Tessellation;
    if (touched)
    {
      std::vector<std::int32_t>& around = this->Neighbours;
      around.clear();
      t.AppendNeighbours(this->EngineOfGauge[g], around);
      const Box2& box = this->BoundsOfGauge(g);
      for (const std::int32_t id : around)
      {
        this->TileBounds[id].Extend(box);
        touched->push_back(id);
      }
    }
    t.Remove(this->EngineOfGauge[g]);
    this->RemovedId[g] = this->EngineOfGauge[g];
    this->EngineOfGauge[g] = NotInTessellation;
    this->Used[g] = 0;
    if (!t.IsTwoDimensional())
    {
      touched = nullptr;
    }
  }

  /// Deferred gauges next to the removed ones: their tiles grew, so their boxes did. One whose
  /// box now reaches the catchment is removed for real (which grows its neighbours' boxes: they
  /// are checked in turn, being appended to touched). A deferred gauge is in the tessellation:
  /// its flag is cleared before it is removed.
  void RemoveDeferredThatGrew(std::vector<std::int32_t>*& touched)
  {
    for (std::size_t k = 0; touched && k < touched->size(); ++k)
    {
      const std::int32_t id = (*touched)[k];
      if (this->Deferred[id] && !this->ClearOfCatchment(this->TileBounds[id]))
      {
        this->Deferred[id] = 0;
        this->RemoveGauge(this->GaugeOfEngine[id], touched);
      }
    }
  }

  /// Apply's insertion of gauge g (under its old engine id when it had one): its neighbours
  /// touched (when listed), and its box their boxes joined; touched becomes null when the
  /// tessellation is not two-dimensional after it.
  void InsertGauge(std::int32_t g, std::vector<std::int32_t>*& touched)
  {
    DirichletTessellation& t = *this->Tessellation;
    std::int32_t id = this->RemovedId[g];
    if (id >= 0)
    {
      t.Reinsert(id, this->PresentNear(g));
    }
    else
    {
      id = t.Insert(this->GaugesXY[g], this->PresentNear(g));
    }
    if (t.Status(id) != PointStatus::Accepted)
    {
      // Never: gauges lie inside the window, and one gauge per place is in the tessellation.
      throw std::logic_error(GaugeLabel(static_cast<std::size_t>(g), this->Settings.GaugeNames) +
        " is not a vertex of the tessellation after its insertion");
    }
    this->EngineOfGauge[g] = id;
    this->Used[g] = 1;
    if (static_cast<std::size_t>(id) >= this->GaugeOfEngine.size())
    {
      this->GaugeOfEngine.resize(id + 1, NotInTessellation);
    }
    if (static_cast<std::size_t>(id) >= this->TileBounds.size() && this->Settings.Incremental)
    {
      this->TileBounds.resize(id + 1);
      this->Deferred.resize(id + 1, 0);
    }
    this->GaugeOfEngine[id] = g;
    if (!touched || !t.IsTwoDimensional())
    {
      touched = nullptr;
      return;
    }
    std::vector<std::int32_t>& around = this->Neighbours;
    around.clear();
    t.AppendNeighbours(id, around);
    Box2 box = this->TileBounds[around.front()];
    for (const std::int32_t neighbour : around)
    {
      box.Extend(this->TileBounds[neighbour]);
      touched->push_back(neighbour);
    }
    this->TileBounds[id] = box;
  }

  /// Renumbers the engine's triangles along the gauges' Hilbert order once a sixteenth of them
  /// were made since the last time (DirichletTessellation::OrderTrianglesByVertex): insertions
  /// take the slots that removals freed anywhere, and the tiles derived around the changed
  /// gauges then miss the cache at each ring step. In the synthetic 100k-gauge stream the
  /// derivation took 25-35% less time after an ordering; one costs some 1.5-3 ms (every 14 steps
  /// or so there, under 0.2 ms per step).
  void KeepTrianglesLocal()
  {
    DirichletTessellation& t = *this->Tessellation;
    if (16 * t.ScatteredTriangleCount() > t.Origin().size() / 3)
    {
      t.OrderTrianglesByVertex();
    }
  }

  /// Clips the (new) tiles and caches their areas, in chunks on the cores when there are enough
  /// of them: each tile is clipped and measured on its own (writing only its gauge's entries), so
  /// the areas are the same bits on any number of threads, and an error is the one the first
  /// failing tile in order gives. A tile costs some 0.3 us on an equal-area plane and some 0.1-1
  /// ms measured geodesically (its densified rings unprojected and summed by GeographicLib).
  void Refresh(const TileSet& tiles)
  {
    const std::int64_t count = static_cast<std::int64_t>(tiles.PointIds.size());
    const std::vector<std::int32_t> bounds = parallel::ChunkBounds(
      static_cast<std::int32_t>(count), parallel::ThreadCount(count, this->ClipsPerThread()));
    const std::size_t chunks = bounds.size() - 1;
    this->ClippingPass(chunks,
      [&]
      {
        parallel::RunChunks(chunks,
          [&](std::size_t chunk)
          {
            for (std::int32_t k = bounds[chunk]; k < bounds[chunk + 1]; ++k)
            {
              this->Store(tiles.PointIds[k],
                &tiles.Vertices[tiles.Offsets[k]],
                static_cast<std::size_t>(tiles.Offsets[k + 1] - tiles.Offsets[k]),
                this->Scratch[chunk]);
            }
          });
      });
  }

  /// Tiles clipped and measured per thread: enough to pay for a thread's start.
  std::int64_t ClipsPerThread() const
  {
    return this->Method == AreaMethod::EqualAreaPlane ? 1000 : 4;
  }

  /// Runs a clipping pass (run, in at most `chunks` chunks, writing only Scratch[0, chunks)), then
  /// sets PositiveArea's bits as its threads noted them: also when a tile's clipping throws, so
  /// that the bits agree with the areas stored before it.
  template<class Pass>
  void ClippingPass(std::size_t chunks, const Pass& run)
  {
    if (this->Scratch.size() < chunks)
    {
      this->Scratch.resize(chunks);
    }
    try
    {
      run();
    }
    catch (...)
    {
      this->ApplyPositiveAreas(chunks);
      throw;
    }
    this->ApplyPositiveAreas(chunks);
  }

  /// Caches the clipped area (and, when updating, the box) of engine point id's tile, and notes
  /// its bit of PositiveArea. (The note first: should it fail to allocate, no area is stored
  /// without its bit.)
  void Store(std::int32_t id, const Point2* tile, std::size_t size, ClipScratch& scratch)
  {
    const std::int32_t g = this->GaugeOfEngine[id];
    const double area = this->ClippedArea(tile, size, static_cast<std::size_t>(g), scratch);
    NotePositiveArea(g, area, scratch);
    this->CachedArea[g] = area;
    if (this->Settings.Incremental)
    {
      this->TileBounds[id] = BoundsOf(tile, size);
    }
  }

  /// The box of gauge g's tile (g in the tessellation).
  const Box2& BoundsOfGauge(std::int32_t g) const
  {
    return this->TileBounds[this->EngineOfGauge[g]];
  }

  /// Whether a tile inside box is clear of the catchment (clipped area 0).
  bool ClearOfCatchment(const Box2& box) const
  {
    const Box2& c = this->Region->Bounds();
    const double m = this->ClearMargin;
    return box.XMax < c.XMin - m || box.XMin > c.XMax + m || box.YMax < c.YMin - m ||
      box.YMin > c.YMax + m;
  }

  /// Every tile, from the whole tessellation.
  std::size_t DeriveAll()
  {
    const TileSet tiles = TessellationDual(*this->Tessellation).Tiles();
    this->Refresh(tiles);
    return tiles.PointIds.size();
  }

  /// Only the tiles whose areas may have changed: those of the inserted gauges and of the gauges
  /// that Apply touched (engine ids), and with degenerate faces their face mates. Everything else
  /// keeps its cached area. Of these, those whose boxes (grown, or joined for inserted gauges) are
  /// clear of the catchment are not derived: their clipped area is 0. Returns (tiles derived, tiles
  /// found clear by their boxes). Works in engine ids: the touched points are near each other in
  /// them, where their gauge numbers are anywhere.
  std::pair<std::size_t, std::size_t> DeriveChanged(const std::vector<std::int32_t>& touched,
    const std::vector<std::int32_t>& inserted)
  {
    const DirichletTessellation& t = *this->Tessellation;
    std::vector<char>& marked = this->Marked;
    marked.assign(this->GaugeOfEngine.size(), 0);
    std::vector<std::int32_t> changed;
    std::size_t clear = 0;
    const auto consider = [&](std::int32_t id)
    {
      // (A touched gauge may have been removed, or its removal deferred, later in the step.)
      if (marked[id] || this->Deferred[id] || t.Status(id) != PointStatus::Accepted)
      {
        return;
      }
      marked[id] = 1;
      if (this->ClearOfCatchment(this->TileBounds[id]))
      {
        this->ClearArea(this->GaugeOfEngine[id]);
        ++clear;
      }
      else
      {
        changed.push_back(id);
      }
    };
    // Inserted gauges first (an inserted gauge is touched again by later insertions next to it).
    for (const std::int32_t g : inserted)
    {
      consider(this->EngineOfGauge[g]);
    }
    for (const std::int32_t id : touched)
    {
      consider(id);
    }
    if (!t.KnownFreeOfCocircularTriangles())
    {
      // A degenerate face takes its centre from its first three points (tiles.h), so a step that
      // changes its points can move that centre by an ulp in the tile of each of its points, not
      // only in those of the changed gauges' neighbours. Such a face has a touched point or an
      // inserted one, so their face mates complete the list.
      for (const std::int32_t id : ComputeFaceMatesOf(t, this->ChangedIds(touched, inserted)).Ids)
      {
        consider(id);
      }
    }
    return { this->DeriveListed(changed), clear };
  }

  /// The engine ids of the touched gauges, then of the inserted ones (gauge numbers).
  std::vector<std::int32_t> ChangedIds(const std::vector<std::int32_t>& touched,
    const std::vector<std::int32_t>& inserted) const
  {
    std::vector<std::int32_t> ids = touched;
    for (const std::int32_t g : inserted)
    {
      ids.push_back(this->EngineOfGauge[g]);
    }
    return ids;
  }

  /// DeriveChanged's tiles: those of the listed engine ids (sorted here), derived, clipped and
  /// stored. Returns how many were derived.
  std::size_t DeriveListed(std::vector<std::int32_t>& changed)
  {
    // Neighbouring tiles one after the other: their faces share cache lines. Each tile is
    // clipped as soon as it is made, on the thread that made it (while it is in the cache).
    SortDistinctIntegers(changed, this->GaugeOfEngine.size(), this->SortBits);
    const std::size_t maxChunks = parallel::ThreadLimit();
    std::size_t derived = 0;
    this->ClippingPass(maxChunks,
      [&]
      {
        derived = VisitTilesOf(
          *this->Tessellation,
          changed,
          maxChunks,
          std::min<std::int64_t>(this->ClipsPerThread(), LocalTilesPerThread),
          [this](std::size_t chunk, std::int32_t id, const Point2* tile, std::size_t size)
          { this->Store(id, tile, size, this->Scratch[chunk]); },
          &this->LocalTiles);
      });
    return derived;
  }
};

namespace
{

/// Per gauge, the smallest gauge id at its place: gauges within `metres` of a gauge of a place
/// (in id order) join it. On a grid of cells at least a millimetre wide, so that a gauge is
/// compared only with the gauges in the 3 x 3 cells about it.
std::vector<std::int32_t> GroupByPlace(const std::vector<Point2>& xy, double metres)
{
  const double cell = std::max(metres, 1e-3);
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::int32_t>> cells;
  std::vector<std::int32_t> first(xy.size());
  for (std::size_t g = 0; g < xy.size(); ++g)
  {
    const std::int64_t i = static_cast<std::int64_t>(std::floor(xy[g].x / cell));
    const std::int64_t j = static_cast<std::int64_t>(std::floor(xy[g].y / cell));
    first[g] = static_cast<std::int32_t>(g);
    for (std::int64_t di = -1; di <= 1; ++di)
    {
      for (std::int64_t dj = -1; dj <= 1; ++dj)
      {
        const auto found = cells.find({ i + di, j + dj });
        if (found == cells.end())
        {
          continue;
        }
        for (const std::int32_t h : found->second)
        {
          if (first[h] < first[g] && std::hypot(xy[g].x - xy[h].x, xy[g].y - xy[h].y) <= metres)
          {
            first[g] = first[h];
          }
        }
      }
    }
    cells[{ i, j }].push_back(static_cast<std::int32_t>(g));
  }
  return first;
}

[[noreturn]] void ThrowInvalidLonLat(const std::string& what, const Point2& p)
{
  // (metres say what is wrong themselves; a typo is told which coordinate is out of range)
  const std::string note = ProjectedCoordinatesNote(p);
  throw InputError(what + " has an invalid longitude/latitude (" + NumberText(p.x) + ", " +
    NumberText(p.y) + ")" + (note.empty() ? ": " + LonLatFault(p) : note));
}

/// An edge that reads two ways round the globe (EdgeReadsBothWays) makes two different
/// catchments (a box from -100 to 100 was measured 20% smaller, on the other side of the globe,
/// with no message): refused.
void CheckEdgeReading(const Point2& a, const Point2& b, std::size_t ring, std::size_t segment)
{
  if (EdgeReadsBothWays(a, b))
  {
    // The middle longitude of each reading, and the end written for the other: b moved by 360
    // towards a (-100 to 100 becomes -100 to -260, 10 to 200 becomes 10 to -160).
    const double written = std::abs(b.x - a.x);
    const double straightMiddle = 0.5 * (a.x + b.x);
    const double otherMiddle = std::remainder(straightMiddle + 180.0, 360.0);
    const double otherEnd = b.x - std::copysign(360.0, b.x - a.x);
    throw InputError("catchment ring " + std::to_string(ring) + " segment " +
      std::to_string(segment) + " runs from longitude " + NumberText(a.x) + " to " +
      NumberText(b.x) + ", " + NumberText(written) +
      " degrees as written: it can be read either way round the globe (straight in lon/lat, "
      "through longitude " +
      NumberText(straightMiddle) + ", or " + NumberText(360.0 - written) +
      " degrees the other way, through longitude " + NumberText(otherMiddle) +
      "). Add a vertex in between for the first; for the second, write its end as " +
      NumberText(otherEnd));
  }
}

/// For a catchment ring found to have no area: why, where one of its segments runs along a
/// parallel from longitude -180 to 180 (or more): the whole parallel as written, but no segment as
/// the edges are read (the shorter way round). A band of latitude round the globe, -180..180 by
/// -60..60, was said to have "fewer than 3 distinct vertices" and no more. "" for other rings
/// (such a segment in a ring that keeps its area, as where a ring gives both 180 and -180 on one
/// parallel, is fine: it has no length). At a pole the two ends are one point either way.
std::string RoundTheGlobeNote(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& lonlat,
  std::size_t ring)
{
  const std::size_t begin = offsets[ring], end = offsets[ring + 1];
  for (std::size_t k = begin; k < end; ++k)
  {
    const Point2& a = lonlat[k];
    const Point2& b = lonlat[NextInRing(k, begin, end)];
    if (std::abs(b.x - a.x) >= 360.0 && a.y == b.y && std::abs(a.y) < 90.0)
    {
      return ": its segment " + std::to_string(k - begin) + " runs along latitude " +
        NumberText(a.y) + " from longitude " + NumberText(a.x) + " to " + NumberText(b.x) +
        ", once round the globe as written but no segment as the edges are read (the shorter way "
        "round). A catchment that goes all the way round the globe (a band of latitude) is not "
        "taken: it cannot be laid flat in one projection";
    }
  }
  return std::string();
}

/// Throws InputError naming the ring and vertex of a finite catchment vertex out of range (NaN
/// and infinite ones are left to ValidateRings, which names them so), or the ring and segment of
/// an edge that can be read two ways (CheckEdgeReading).
void CheckCatchmentLonLat(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& lonlat)
{
  for (std::size_t r = 0; r + 1 < offsets.size(); ++r)
  {
    const std::size_t begin = offsets[r], end = offsets[r + 1]; // (CheckRingOffsets first)
    for (std::size_t k = begin; k < end; ++k)
    {
      const Point2& p = lonlat[k];
      if (std::isfinite(p.x) && std::isfinite(p.y) && !InLonLatRange(p))
      {
        ThrowInvalidLonLat(
          "catchment ring " + std::to_string(r) + " vertex " + std::to_string(k - begin), p);
      }
    }
    for (std::size_t k = begin; k < end; ++k)
    {
      CheckEdgeReading(lonlat[k], lonlat[NextInRing(k, begin, end)], r, k - begin);
    }
  }
}

/// Point i of the n that cut edge a-b into pieces (point 0 is a). The points are interpolated
/// from the edge's lesser end (x, then y) whichever way the edge runs, so that two rings sharing
/// an edge (adjacent sub-catchments, running it opposite ways) get the same points to the last
/// bit, and the shared stretch stays shared once projected rather than becoming slivers.
Point2 DensifiedPoint(const Point2& a, const Point2& b, int i, int n)
{
  if (i == 0)
  {
    return a;
  }
  return ComesFirst(a, b) ? InterpolateLonLat(a, b, double(i) / n)
                          : InterpolateLonLat(b, a, double(n - i) / n);
}

/// Tile k's outline from its pieces in lon/lat (lonLat, TilePieceOffsets[k] .. [k+1] of out):
/// cut at the 180th meridian first (or its copy 360 degrees on, as its longitudes run) when it
/// crosses it, so that each polygon lies on one side of it (meridian_cut.h).
RegionOutlines OutlineOfTile(const ClippedRings& lonLat,
  const ClippedTilesLonLat& out,
  std::size_t k)
{
  const std::size_t first = out.TilePieceOffsets[k], last = out.TilePieceOffsets[k + 1];
  const std::size_t begin = lonLat.RingOffsets[first], end = lonLat.RingOffsets[last];
  const Box2 box = BoundsOf(&lonLat.Vertices[begin], end - begin);
  const double meridian = 180.0 + 360.0 * std::ceil((box.XMin - 180.0) / 360.0);
  if (!(box.XMin < meridian && meridian < box.XMax))
  {
    return OutlinesOfPieces(lonLat, first, last);
  }
  RegionOutlines sides;
  for (const ClippedRings& side : CutAtMeridian(lonLat, first, last, meridian))
  {
    AppendOutlines(OutlinesOfPieces(side, 0, side.RingOffsets.size() - 1), sides);
  }
  return sides;
}

/// Each tile's pieces in lon/lat joined into its outline (piece_outlines.h), appended to
/// out.Outlines with TileOutlineOffsets: the tiles on the cores, joined in order (the same
/// outlines on any number of threads).
void AppendOutlinesOfTiles(const ClippedRings& lonLat, ClippedTilesLonLat& out)
{
  const std::size_t tiles = out.Gauges.size();
  std::vector<RegionOutlines> outlines(tiles);
  parallel::RunClaimed(tiles,
    parallel::ThreadCount(std::int64_t(tiles), 16),
    [&](std::size_t k, std::size_t) { outlines[k] = OutlineOfTile(lonLat, out, k); });
  for (const RegionOutlines& outline : outlines)
  {
    AppendOutlines(outline, out.Outlines);
    out.TileOutlineOffsets.push_back(out.Outlines.PolygonOffsets.size() - 1);
  }
}

/// A gauge's lon/lat as projected: at a pole, whatever its longitude, at the central meridian.
/// Every longitude names the pole (a file may give the South Pole's station as 0, -90 and another
/// as 139.27, -90), but a conic projection makes the pole an arc: two such gauges were two places
/// some 20 km apart, each weighted, and not reported as co-located. At the central meridian, they
/// are one place, at the middle of the arc.
Point2 GaugePlace(const Point2& lonlat, const GeographicProjection& projection)
{
  return std::abs(lonlat.y) == 90.0 ? Point2{ projection.CentralMeridian(), lonlat.y } : lonlat;
}

/// A count held in a double as a whole number, or to 3 figures beyond 1e15 ("8e+300"; one that
/// overflowed, "more than 1e308").
std::string CountText(double count)
{
  if (!std::isfinite(count))
  {
    return "more than 1e308";
  }
  if (count < 1e15)
  {
    return std::to_string(static_cast<long long>(count));
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", count);
  return text;
}

/// Per catchment segment (ring vertex k to the next), the pieces it is cut into at most
/// edgeDegrees long. Throws InputError when they make more than MaxCatchmentVertices vertices in
/// all: some 100 bytes each once projected and indexed, so such a catchment would take gigabytes
/// (a comb of thousands of teeth tens of degrees long ran out of memory without a word). A real
/// outline stays far below: 20 million pieces of 0.01 degrees are 200000 degrees of boundary.
std::vector<int> DensifiedPieceCounts(const CleanRings& rings, double edgeDegrees)
{
  constexpr std::size_t MaxCatchmentVertices = 20000000;
  std::vector<int> pieces(rings.Vertices.size());
  double total = 0.0; // the pieces wanted, before DensifiedPieceCount's cap of an edge
  for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
  {
    const std::size_t begin = rings.RingOffsets[r], end = rings.RingOffsets[r + 1];
    for (std::size_t k = begin; k < end; ++k)
    {
      const Point2& a = rings.Vertices[k];
      const Point2& b = rings.Vertices[NextInRing(k, begin, end)];
      const double wanted = WantedPieceCount(a, b, edgeDegrees);
      if (wanted > double(MaxDensifiedPieces))
      {
        // (cut into fewer, its pieces would be longer than asked, without a word)
        throw InputError("catchment ring " + std::to_string(r) + " segment " +
          std::to_string(rings.SourceIndex[k]) + ", cut into pieces of at most " +
          NumberText(edgeDegrees) + " degrees, makes " + CountText(wanted) +
          " pieces, more than an edge may (" + std::to_string(MaxDensifiedPieces) +
          "): cut the edges more coarsely (ArealAverageSettings::CatchmentEdgeDegrees, in the "
          "core's C++ API)");
      }
      pieces[k] = static_cast<int>(wanted); // (DensifiedPieceCount's, within its cap)
      total += wanted;
    }
  }
  if (total > double(MaxCatchmentVertices))
  {
    throw InputError("the catchment's edges, cut into pieces of at most " +
      NumberText(edgeDegrees) + " degrees to follow their lon/lat lines once projected, make " +
      CountText(total) + " vertices, more than " + std::to_string(MaxCatchmentVertices) +
      " (some 100 bytes each): simplify the outline, or cut its edges more coarsely "
      "(ArealAverageSettings::CatchmentEdgeDegrees, in the core's C++ API)");
  }
  return pieces;
}

/// Throws InputError when the catchment's rings cancel out under the even-odd rule (a file
/// holding a basin and its sub-basins: each sub-basin becomes a hole, and with all of them
/// nothing is left). Every weight would then be 0 / 0 and every mean empty, without an error.
void CheckCatchmentHasArea(const Catchment& region)
{
  if (region.RingsCancelOut())
  {
    throw InputError("the catchment has no area: " + region.RingsCancelOutText() +
      ". A basin given together with its sub-basins does this: give the basin alone, or each "
      "sub-basin as a catchment of its own");
  }
}

/// The gauges' places and the settings, checked before anything is built from them.
void CheckGaugesAndSettings(const std::vector<Point2>& gaugesLonLat,
  const ArealAverageSettings& settings)
{
  for (std::size_t g = 0; g < gaugesLonLat.size(); ++g)
  {
    if (!InLonLatRange(gaugesLonLat[g])) // NaN and infinities included
    {
      ThrowInvalidLonLat(GaugeLabel(g, settings.GaugeNames), gaugesLonLat[g]);
    }
  }
  if (!(settings.CoLocatedMetres >= 0.0) || !std::isfinite(settings.CoLocatedMetres))
  {
    throw InputError("CoLocatedMetres must be a finite distance >= 0, not " +
      NumberText(settings.CoLocatedMetres));
  }
  CheckSettingsRange(settings);
  if (!settings.GaugeNames.empty() && settings.GaugeNames.size() != gaugesLonLat.size())
  {
    throw InputError("GaugeNames has " + std::to_string(settings.GaugeNames.size()) +
      " names for " + std::to_string(gaugesLonLat.size()) + " gauges");
  }
}

/// The catchment's rings in lon/lat, validated as the edges are read: a ring that jumps the 180th
/// meridian runs on past it; a vertex a hair off another ring's edge (a sub-basin border's
/// T-junction, rounded) is put on it (snappedVertices: how many).
CleanRings ValidCatchmentRings(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& lonLat,
  std::size_t& snappedVertices)
{
  try
  {
    CheckRingOffsets(offsets, lonLat.size());
  }
  catch (const InputError& e) // (an offset beyond the vertices was read past their end)
  {
    throw InputError(std::string("catchment: ") + e.what());
  }
  CheckCatchmentLonLat(offsets, lonLat);
  const SnappedRings snapped = SnapVerticesOntoSegments(
    offsets, RingsInOneTurn(offsets, lonLat), ArealAverageSettings::SharedBorderDegrees);
  snappedVertices = snapped.Inserted;
  try
  {
    return WithContactsAsVertices(snapped.Inserted == 0
        ? ValidateRings(snapped.Offsets, snapped.Vertices)
        : ValidateRings(snapped.Offsets, snapped.Vertices, &snapped.SegmentOf));
  }
  catch (const RingError& e)
  {
    // Only where the ring as read lies on one line (a bow tie across the 180th meridian was told
    // it went round the globe).
    const std::size_t r = e.Rings.size() == 1 ? e.Rings[0] : snapped.Offsets.size();
    const bool flat = r + 1 < snapped.Offsets.size() &&
      AllOnOneLine(
        &snapped.Vertices[snapped.Offsets[r]], snapped.Offsets[r + 1] - snapped.Offsets[r]);
    const std::string note = flat ? RoundTheGlobeNote(offsets, lonLat, r) : std::string();
    if (note.empty())
    {
      throw;
    }
    throw RingError(e.what() + note, e.Rings, e.Segments);
  }
}

/// The method asked for, or for Automatic the one the projection allows; EqualAreaPlane asked of
/// a projection that does not keep areas is an InputError.
AreaMethod ChooseAreaMethod(AreaMethod asked, const ProjectionParameters& parameters)
{
  const bool equalArea = KeepsAreas(parameters);
  if (asked == AreaMethod::EqualAreaPlane && !equalArea)
  {
    throw InputError(std::string("areas in the projected plane (EqualAreaPlane) are ellipsoidal "
                                 "areas only in an equal-area projection at scale 1, and ") +
      ProjectionKindName(parameters.Kind) +
      (KeepsAreas(parameters.Kind)
          ? " with scale factor k0 = " + NumberText(parameters.ScaleFactor) + " is not one"
          : " is not one") +
      ": use the GeodesicPolygon or Automatic area method");
  }
  if (asked == AreaMethod::Automatic)
  {
    return equalArea ? AreaMethod::EqualAreaPlane : AreaMethod::GeodesicPolygon;
  }
  return asked;
}

/// The catchment's rings, projected: edges straight in lon/lat are cut into pieces first.
/// segmentOf: per projected vertex, the caller's segment it lies on.
void ProjectDensified(const CleanRings& rings,
  double edgeDegrees,
  const GeographicProjection& projector,
  std::vector<std::size_t>& offsets,
  std::vector<Point2>& projected,
  std::vector<std::size_t>& segmentOf)
{
  const std::vector<int> pieceCounts = DensifiedPieceCounts(rings, edgeDegrees);
  offsets.assign(1, 0);
  for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
  {
    const std::size_t begin = rings.RingOffsets[r], end = rings.RingOffsets[r + 1];
    for (std::size_t k = begin; k < end; ++k)
    {
      const Point2& a = rings.Vertices[k];
      const Point2& b = rings.Vertices[NextInRing(k, begin, end)];
      const int pieces = pieceCounts[k];
      for (int i = 0; i < pieces; ++i)
      {
        projected.push_back(projector.Forward(DensifiedPoint(a, b, i, pieces)));
        segmentOf.push_back(rings.SourceIndex[k]);
      }
    }
    offsets.push_back(projected.size());
  }
}

/// The projected catchment. The rings were valid in lon/lat (in one turn of the globe,
/// RingsInOneTurn, with contacts made vertices), so where they cross once projected, it is where
/// edges straight in lon/lat, cut into pieces and projected, pass within rounding of each other:
/// the error then names the caller's segments, not the densified pieces'.
std::unique_ptr<Catchment> ProjectedCatchment(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& projected,
  const std::vector<std::size_t>& segmentOf)
{
  try
  {
    return std::unique_ptr<Catchment>(new Catchment(offsets, projected));
  }
  catch (const InputError&)
  {
    try
    {
      ValidateRings(offsets, projected, &segmentOf);
    }
    catch (const InputError& e)
    {
      const std::string message = "the catchment meets itself once projected, though not in "
                                  "lon/lat: " +
        std::string(e.what()) +
        ". Its edges, straight in lon/lat, are cut into pieces and projected: rings or edges "
        "that pass within rounding of each other can meet so; make them meet at a vertex, or "
        "move them apart";
      if (const auto* rings = dynamic_cast<const RingError*>(&e))
      {
        throw RingError(message, rings->Rings, rings->Segments); // (a caller names them)
      }
      throw InputError(message);
    }
    throw;
  }
}

} // namespace

void ThiessenArealAverage::State::ChooseProjection(const CleanRings& rings)
{
  if (this->Settings.HaveProjection)
  {
    this->Parameters = this->Settings.Projection;
  }
  else
  {
    // Fitted to the catchment alone: the tiles matter only there, the conic's distances are
    // truest where it is fitted (so the tiles there come closest to the geodesically nearest
    // gauges), and the result does not move with gauges far away (a gauge never reporting, or
    // one with a mistyped coordinate, fitted in, moved Colorado's monthly means by up to 2%).
    this->Parameters = AutomaticParameters(rings.Vertices);
  }
  this->Projector.reset(new GeographicProjection(this->Parameters));
  this->Method = ChooseAreaMethod(this->Settings.Areas, this->Parameters);
}

// Gauges: projected, and grouped by place (the first of a group is its name).
void ThiessenArealAverage::State::PlaceGauges(const std::vector<Point2>& gaugesLonLat)
{
  this->GaugesXY.resize(gaugesLonLat.size());
  for (std::size_t g = 0; g < gaugesLonLat.size(); ++g)
  {
    try
    {
      this->GaugesXY[g] = this->Projector->Forward(GaugePlace(gaugesLonLat[g], *this->Projector));
    }
    catch (const InputError& e) // it names the place ("point (lon, lat) ..."), not the gauge
    {
      throw InputError(GaugeLabel(g, this->Settings.GaugeNames) + ": " + e.what());
    }
  }
  this->FirstAtPlace = GroupByPlace(this->GaugesXY, this->Settings.CoLocatedMetres);
  for (std::size_t g = 0; g < gaugesLonLat.size(); ++g)
  {
    if (this->FirstAtPlace[g] != static_cast<std::int32_t>(g))
    {
      this->Duplicates.emplace_back(static_cast<std::int32_t>(g), this->FirstAtPlace[g]);
    }
  }
  if (!this->Duplicates.empty())
  {
    this->PlaceShared.assign(gaugesLonLat.size(), 0);
    for (const auto& [copy, first] : this->Duplicates)
    {
      this->PlaceShared[copy] = 1;
      this->PlaceShared[first] = 1;
    }
  }
}

// The catchment, projected (a Catchment, ready to clip tiles), and its area measured as the
// tiles' will be.
void ThiessenArealAverage::State::ProjectCatchment(const CleanRings& rings)
{
  std::vector<std::size_t> offsets;
  std::vector<Point2> projected;
  std::vector<std::size_t> segmentOf;
  ProjectDensified(
    rings, this->Settings.CatchmentEdgeDegrees, *this->Projector, offsets, projected, segmentOf);
  this->Region = ProjectedCatchment(offsets, projected, segmentOf);
  CheckCatchmentHasArea(*this->Region);
  if (this->Method == AreaMethod::EqualAreaPlane)
  {
    this->CatchmentArea = this->Region->Area();
  }
  else
  {
    ClippedRings stored;
    stored.RingOffsets = this->Region->RingOffsets();
    stored.Vertices = this->Region->Vertices();
    this->CatchmentArea = this->MeasureRings(stored, this->Scratch[0]);
  }
}

// The window: every gauge and the whole catchment, padded; the empty tessellation in it, and
// the per-gauge state of the steps.
void ThiessenArealAverage::State::MakeWindow()
{
  Box2 box = this->Region->Bounds();
  for (const Point2& p : this->GaugesXY)
  {
    box.Extend(p);
  }
  const double pad = std::max(this->Settings.Padding, 0.01) * box.LargerSide();
  this->TheWindow.reset(
    new Window(Window::Rectangle(box.XMin - pad, box.XMax + pad, box.YMin - pad, box.YMax + pad)));
  this->Tessellation.reset(new DirichletTessellation(*this->TheWindow));
  const std::size_t n = this->GaugesXY.size();
  if (this->Settings.Incremental)
  {
    this->PrepareUpdates(1e-6 * (box.LargerSide() + 2.0 * pad));
  }
  this->EngineOfGauge.assign(n, NotInTessellation);
  this->CachedArea.assign(n, 0.0);
  this->PositiveArea.assign(BitmapWords(n), 0);
}

// What updating between steps keeps per gauge, and the gauges' order along a curve.
void ThiessenArealAverage::State::PrepareUpdates(double clearMargin)
{
  const std::size_t n = this->GaugesXY.size();
  this->Tessellation->TrackVertexEdges(); // local tile derivation finds its rings in O(1)
  this->TileBounds.resize(n);
  this->Deferred.assign(n, 0);
  this->RemovedId.assign(n, -1);
  this->Used.assign(n, 0);
  this->ClearMargin = clearMargin;
  this->CurveOrder.resize(n);
  std::iota(this->CurveOrder.begin(), this->CurveOrder.end(), 0);
  this->SpatialSort(this->CurveOrder);
  this->CurveRank.resize(n);
  for (std::size_t k = 0; k < this->CurveOrder.size(); ++k)
  {
    this->CurveRank[this->CurveOrder[k]] = static_cast<std::int32_t>(k);
  }
}

ThiessenArealAverage::ThiessenArealAverage(const std::vector<Point2>& gaugesLonLat,
  const std::vector<std::size_t>& catchmentRingOffsets,
  const std::vector<Point2>& catchmentLonLat,
  const ArealAverageSettings& settings)
  : Impl(new State)
{
  State& s = *this->Impl;
  s.Settings = settings;
  CheckGaugesAndSettings(gaugesLonLat, settings);
  const CleanRings rings =
    ValidCatchmentRings(catchmentRingOffsets, catchmentLonLat, s.SnappedVertices);
  s.ChooseProjection(rings);
  s.PlaceGauges(gaugesLonLat);
  s.ProjectCatchment(rings);
  s.MakeWindow();
}

ThiessenArealAverage::~ThiessenArealAverage() = default;

const ProjectionParameters& ThiessenArealAverage::Projection() const
{
  return this->Impl->Parameters;
}

AreaMethod ThiessenArealAverage::Method() const
{
  return this->Impl->Method;
}

const std::vector<std::pair<std::int32_t, std::int32_t>>& ThiessenArealAverage::DuplicateGauges()
  const
{
  return this->Impl->Duplicates;
}

std::vector<char> ThiessenArealAverage::GaugesUsed(const std::vector<double>& values) const
{
  const State& s = *this->Impl;
  if (values.size() != s.FirstAtPlace.size())
  {
    throw InputError("GaugesUsed: " + std::to_string(values.size()) + " values for " +
      std::to_string(s.FirstAtPlace.size()) + " gauges");
  }
  std::vector<char> used(values.size()), taken;
  bool infinite = false;
  MarkFirstAtPlace(values, s.FirstAtPlace, used.data(), taken, infinite);
  return used;
}

std::size_t ThiessenArealAverage::CatchmentVerticesPutOnEdges() const
{
  return this->Impl->SnappedVertices;
}

double ThiessenArealAverage::CatchmentAreaM2() const
{
  return this->Impl->CatchmentArea;
}

const std::vector<Point2>& ThiessenArealAverage::ProjectedGauges() const
{
  return this->Impl->GaugesXY;
}

bool ThiessenArealAverage::GaugeInsideCatchment(std::size_t g) const
{
  if (g >= this->Impl->GaugesXY.size())
  {
    throw InputError("GaugeInsideCatchment: no gauge " + std::to_string(g) + " (there are " +
      std::to_string(this->Impl->GaugesXY.size()) + ")");
  }
  return this->Impl->Region->Contains(this->Impl->GaugesXY[g]);
}

std::vector<std::int32_t> ThiessenArealAverage::CatchmentRingsAround(std::size_t r) const
{
  const Catchment& region = *this->Impl->Region;
  if (r >= region.RingOffsets().size() - 1) // (r + 1 wrapped round at SIZE_MAX)
  {
    throw InputError("CatchmentRingsAround: no ring " + std::to_string(r) + " (there are " +
      std::to_string(region.RingOffsets().size() - 1) + ")");
  }
  return region.EnclosingRings(r);
}

// The step's reported changes applied to the tessellation: the gauges that stopped reporting
// removed (or their removals deferred, DeferClearRemovals), those that started inserted; returns
// them and whether the tiles can be derived locally. Locally when updating a two-dimensional
// tessellation, with at most a fifth of the gauges changing; otherwise every tile. A
// two-dimensional tessellation before the update means that every cached area is current (the
// first step, or one after a step without reports, starts from an empty tessellation).
ThiessenArealAverage::State::Changes ThiessenArealAverage::State::ApplyReportedChanges()
{
  Changes changes;
  std::vector<std::int32_t> removed;
  this->ListChanges(this->Wanted, removed, changes.Inserted);
  const std::size_t n = this->GaugesXY.size();
  const bool local =
    this->Tessellation->IsTwoDimensional() && 5 * (removed.size() + changes.Inserted.size()) <= n;
  if (local)
  {
    changes.Deferred = this->DeferClearRemovals(removed);
  }
  else
  {
    this->TakeAllDeferred(removed);
  }
  changes.Local = this->Apply(removed, changes.Inserted, local ? &changes.Touched : nullptr);
  this->KeepTrianglesLocal();
  return changes;
}

void ThiessenArealAverage::State::RebuildFromWanted()
{
  std::vector<std::int32_t> active;
  for (std::size_t g = 0; g < this->Wanted.size(); ++g)
  {
    if (this->Wanted[g])
    {
      active.push_back(static_cast<std::int32_t>(g));
    }
  }
  this->Rebuild(active);
}

// Weights of every reporting gauge from the cached areas (current for all of them), ascending:
// the gauges both used and with a positive area, read off their bitmaps a word at a time; and the
// step's mean. In blocks of WordsPerWeighBlock words on the cores: the pass reads the areas and
// writes the lists (1.5 MB among 100k gauges), and one thread took 80 us of a 100k-gauge update,
// two 45. Each block writes its part of the lists, sized first, and sums its weights in gauge
// order; the blocks' sums are added in block order. (Up to 16384 gauges that is the one order of
// a serial pass.) step is Step's fresh result, its lists empty.
void ThiessenArealAverage::State::Weigh(const std::vector<double>& values, ArealStep& step) const
{
  const std::vector<std::size_t> starts = this->WeighBlockStarts();
  const std::size_t blocks = starts.size() - 1;
  step.Gauges.resize(starts.back());
  step.Weights.resize(starts.back());
  step.AreasM2.resize(starts.back());
  std::vector<std::pair<double, double>> sums(blocks);
  // (A block per thread at least: a second thread for a sliver of a block would cost more than
  // it saves, and when another object's pass holds the kept threads, one is started for it.)
  const std::vector<std::int32_t> bounds = parallel::ChunkBounds(static_cast<std::int32_t>(blocks),
    std::min(blocks,
      parallel::ThreadCount(static_cast<std::int64_t>(this->WantedBits.size()),
        static_cast<std::int64_t>(WordsPerWeighBlock))));
  parallel::RunChunks(bounds.size() - 1,
    [&](std::size_t chunk)
    {
      for (std::int32_t b = bounds[chunk]; b < bounds[chunk + 1]; ++b)
      {
        sums[b] = this->WeighBlock(static_cast<std::size_t>(b), starts[b], values, step);
      }
    });
  double weighted = 0.0, weightSum = 0.0;
  for (const auto& [blockWeighted, blockWeights] : sums)
  {
    weighted += blockWeighted;
    weightSum += blockWeights;
  }
  step.StationsWeighted = static_cast<int>(step.Gauges.size());
  step.CoveredFraction = weightSum;
  step.Mean = weightSum > 0.0 ? weighted / weightSum : std::numeric_limits<double>::quiet_NaN();
}

/// Where each of Weigh's blocks starts in the lists of weighted gauges, and their total last.
std::vector<std::size_t> ThiessenArealAverage::State::WeighBlockStarts() const
{
  const std::size_t words = this->WantedBits.size();
  const std::size_t blocks =
    std::max<std::size_t>(1, (words + WordsPerWeighBlock - 1) / WordsPerWeighBlock);
  std::vector<std::size_t> starts(blocks + 1, 0);
  for (std::size_t w = 0; w < words; ++w)
  {
    starts[w / WordsPerWeighBlock + 1] +=
      static_cast<std::size_t>(SetBitCount(this->WantedBits[w] & this->PositiveArea[w]));
  }
  for (std::size_t b = 0; b < blocks; ++b)
  {
    starts[b + 1] += starts[b];
  }
  return starts;
}

/// Weigh's block `block`: its weighted gauges, weights and areas written from place `first` of
/// the lists; returns its sums of weight * value and of weights, in gauge order.
std::pair<double, double> ThiessenArealAverage::State::WeighBlock(std::size_t block,
  std::size_t first,
  const std::vector<double>& values,
  ArealStep& step) const
{
  const std::size_t end = std::min(this->WantedBits.size(), (block + 1) * WordsPerWeighBlock);
  double weighted = 0.0, weightSum = 0.0;
  std::size_t k = first;
  for (std::size_t w = block * WordsPerWeighBlock; w < end; ++w)
  {
    for (std::uint64_t word = this->WantedBits[w] & this->PositiveArea[w]; word != 0;
         word &= word - 1)
    {
      const std::int32_t g = static_cast<std::int32_t>(64 * w + LowestSetBit(word));
      const double area = this->CachedArea[g];
      const double weight = area / this->CatchmentArea;
      step.Gauges[k] = g;
      step.Weights[k] = weight;
      step.AreasM2[k] = area;
      ++k;
      weighted += weight * values[g];
      weightSum += weight;
    }
  }
  return { weighted, weightSum };
}

ArealStep ThiessenArealAverage::Step(const std::vector<double>& values)
{
  State& s = *this->Impl;
  const std::size_t n = s.GaugesXY.size();
  if (values.size() != n)
  {
    throw InputError("a step has " + std::to_string(values.size()) + " values for " +
      std::to_string(n) + " gauges");
  }
  ArealStep step;
  step.StationsUsed = s.MarkReporting(values);
  State::Changes changes;
  if (s.Settings.Incremental)
  {
    changes = s.ApplyReportedChanges();
  }
  else
  {
    s.RebuildFromWanted();
  }
  step.RemovalsDeferred = static_cast<int>(changes.Deferred);
  if (step.StationsUsed == 0)
  {
    step.Mean = std::numeric_limits<double>::quiet_NaN();
    return step;
  }
  const std::pair<std::size_t, std::size_t> derived = changes.Local
    ? s.DeriveChanged(changes.Touched, changes.Inserted)
    : std::make_pair(s.DeriveAll(), std::size_t(0));
  step.TilesDerived = static_cast<int>(derived.first);
  step.TilesFoundClear = static_cast<int>(derived.second);
  s.Weigh(values, step);
  return step;
}

ClippedTilesLonLat ThiessenArealAverage::CurrentClippedTiles(double maxStepMetres) const
{
  CheckStepMetres(maxStepMetres, "CurrentClippedTiles' step");
  // Read only, with scratch of its own: two threads displaying one average at once had shared
  // Scratch[0] (wrong areas, freed blocks freed again), where a const method promised none.
  // (One scratch per chunk of the passes on the cores.)
  const State& s = *this->Impl;
  std::vector<State::ClipScratch> scratch(parallel::ThreadLimit());
  ClippedTilesLonLat out;
  const ClippedRings plane = s.PlanePiecesOfUsedTiles(scratch, out);
  // Neighbouring tiles' pieces take each other's vertices on their common borders, and every
  // edge is cut at the same points from either side, so that they still meet exactly in lon/lat
  // (shared_borders.h).
  const ClippedRings shared = ShareBorderVertices(plane);
  std::vector<char> fans; // per piece: whether it is a fan about its first vertex in lon/lat
  const ClippedRings lonLat = s.PiecesInLonLat(shared, maxStepMetres, scratch, fans);
  AppendOutlinesOfTiles(lonLat, out);
  s.SetDisplayPieces(lonLat, fans, scratch[0], out);
  return out;
}

} // namespace tessera
