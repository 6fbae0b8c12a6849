// Local derivation (tiles.h: ComputeTilesOf, ComputeFaceMatesOf): the tiles and face mates of
// chosen points only, labelling just the faces around them, bit for bit as TessellationDual.
#include "tiles.h"

#include "cache_line.h"
#include "predicates_inline.h"
#include "parallel_chunks.h"
#include "tile_edges.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <unordered_map>
#include <utility>

namespace tessera
{

namespace
{

using namespace tiles_detail;

// Per triangle, the entry LocalFaces gave it (-1: none). A flat table of every triangle, 4 bytes
// each, is far cheaper than the cache misses of hashing when many tiles are derived, and the
// caller may keep one all -1 between calls (entries set back one by one). Without one, a table
// made for the call cost O(triangles) however few tiles it derived (one tile took 226 us at 10^6
// points, 7 us at 10^4): a call that labels few of many triangles hashes them instead.
class TriangleEntries
{
public:
  /// expected: about how many triangles will be labelled (the table is flat beyond 1/64 of them).
  TriangleEntries(std::vector<std::int32_t>* table, std::size_t triangles, std::size_t expected)
    : Flat(table ? *table : this->OwnTable)
    , Hashed(!table && expected * 64 < triangles)
  {
    if (this->Hashed)
    {
      this->Hash.reserve(expected);
    }
    else
    {
      this->Flat.resize(triangles, -1);
    }
  }

  ~TriangleEntries()
  {
    for (const std::int32_t t : this->Written)
    {
      this->Flat[t] = -1;
    }
  }

  TriangleEntries(const TriangleEntries&) = delete;
  TriangleEntries& operator=(const TriangleEntries&) = delete;

  /// Room for this many entries set before the table is set back.
  void Reserve(std::size_t entries)
  {
    if (!this->Hashed)
    {
      this->Written.reserve(entries);
    }
  }

  std::int32_t Find(std::int32_t t) const
  {
    if (!this->Hashed)
    {
      return this->Flat[t];
    }
    const auto found = this->Hash.find(t);
    return found != this->Hash.end() ? found->second : -1;
  }

  void Set(std::int32_t t, std::int32_t value)
  {
    if (this->Hashed)
    {
      this->Hash[t] = value;
      return;
    }
    if (this->Flat[t] == -1)
    {
      this->Written.push_back(t);
    }
    this->Flat[t] = value;
  }

private:
  std::vector<std::int32_t> OwnTable; // (declared before Flat, which may refer to it)
  std::vector<std::int32_t>& Flat;
  std::vector<std::int32_t> Written; // the flat table's entries that are not -1
  const bool Hashed;
  std::unordered_map<std::int32_t, std::int32_t> Hash;
};

// Faces around chosen points, labelled on demand with the full derivation's rules: a face is the
// cluster of exactly co-circular triangles (connected, since the points on an empty circle are
// triangulated by triangles on that circle), labelled by its smallest triangle index, with its
// centre from the same FaceCentre, so the bits match TessellationDual's.
class LocalFaces
{
public:
  /// table: a table indexed by triangle, all -1 between derivations, kept by the caller between
  /// calls; without one, TriangleEntries chooses for the tiles expected (points whose rings are
  /// labelled). Without wantCentres (face mates only) the faces get no centre (View is not used).
  LocalFaces(const Tess& tess,
    bool wantCentres,
    std::size_t tilesExpected,
    std::vector<std::int32_t>* table = nullptr)
    : T(tess)
    , WantCentres(wantCentres)
    , FreeOfCocircular(tess.KnownFreeOfCocircularTriangles())
    , EntryOf(table, tess.Origin().size() / 3, 8 * tilesExpected)
  {
    // Room for the faces of tiles near each other (they share most faces: 3.8 per tile derived
    // in the synthetic 100k-gauge updates), so that the lists are not copied as they grow (their
    // reallocations took 4% of an update's instructions, and a third of its writes that missed a
    // simulated 2 MB cache).
    // (Never more than the triangles: a tessellation has some 2 faces per point.)
    const std::size_t faces = std::min(4 * tilesExpected, tess.Origin().size() / 3);
    this->Entries.reserve(faces);
    this->EntryOf.Reserve(faces);
  }

  LocalFaces(const LocalFaces&) = delete;
  LocalFaces& operator=(const LocalFaces&) = delete;

  std::int32_t Label(std::int32_t t) const
  {
    const std::int32_t entry = this->Find(t);
    return entry < 0 ? -2 - t : this->Entries[entry].Label;
  }

  FaceView View(std::int32_t label) const
  {
    if (label < 0)
    {
      return FaceView();
    }
    const Entry& entry = this->Entries[this->Find(label)];
    return { label, entry.Centre, entry.Inside };
  }

  /// The points of triangle t's face, in no particular order (none for a ghost); t must be
  /// resolved.
  void FacePoints(std::int32_t t, const std::int32_t*& begin, const std::int32_t*& end) const
  {
    const std::int32_t index = this->Find(t);
    if (index < 0)
    {
      begin = end = nullptr;
      return;
    }
    const Entry& entry = this->Entries[index];
    begin = entry.PointStart == OwnTriangle ? this->T.Origin().data() + 3 * entry.Label
                                            : this->Points.data() + entry.PointStart;
    end = begin + entry.PointCount;
  }

  // Ghost: a vertex is Tess::Ghost (inline here: this runs for every ring triangle).
  bool Ghost(std::int32_t t) const
  {
    const std::int32_t* v = this->T.Origin().data() + 3 * t;
    return v[0] < 0 || v[1] < 0 || v[2] < 0;
  }

  void Resolve(std::int32_t t)
  {
    if (this->Ghost(t) || this->Find(t) >= 0)
    {
      return; // ghosts stay unlisted: Label gives -2 - t
    }
    if (this->FreeOfCocircular)
    {
      this->ResolveTriangle(t);
      return;
    }
    const auto& org = this->T.Origin();
    const auto& twin = this->T.Twin();
    const std::vector<Point2>& pts = this->T.Points();
    // Flood the triangles on t's circle; members are marked with a placeholder entry. (None
    // when the tessellation is known free of co-circular triangles.)
    constexpr std::int32_t Pending = -2;
    this->Cluster.assign(1, t);
    this->Insert(t, Pending);
    for (std::size_t k = 0; k < this->Cluster.size() && !this->FreeOfCocircular; ++k)
    {
      const std::int32_t s = this->Cluster[k];
      for (std::int32_t side = 0; side < 3; ++side)
      {
        const std::int32_t f = twin[3 * s + side];
        const std::int32_t u = f / 3;
        if (this->Find(u) != -1)
        {
          continue; // listed already: no need to touch its (likely uncached) vertices
        }
        // u shares the edge of f with s, so it is a ghost iff its third vertex is the ghost.
        const std::int32_t d = org[Tess::Prev(f)];
        if (d >= 0 &&
          incircle_fast(pts[org[3 * t]], pts[org[3 * t + 1]], pts[org[3 * t + 2]], pts[d]) == 0)
        {
          this->Insert(u, Pending);
          this->Cluster.push_back(u);
        }
      }
    }
    if (this->Cluster.size() == 1)
    {
      this->ResolveTriangle(t); // (t is marked Pending: set again to its entry there)
      return;
    }
    Entry entry;
    entry.Label = *std::min_element(this->Cluster.begin(), this->Cluster.end());
    entry.PointStart = std::int32_t(this->Points.size());
    for (const std::int32_t s : this->Cluster)
    {
      this->AppendPointsOf(s);
    }
    std::sort(this->Points.begin() + entry.PointStart, this->Points.end());
    this->Points.erase(
      std::unique(this->Points.begin() + entry.PointStart, this->Points.end()), this->Points.end());
    entry.PointCount = std::int32_t(this->Points.size()) - entry.PointStart;
    if (this->WantCentres)
    {
      double error = 0.0;
      entry.Centre = FaceCentre(
        pts, this->Points.data() + entry.PointStart, std::size_t(entry.PointCount), error);
      entry.Inside = CentreInside(this->T, entry.Label, entry.Centre, error);
    }
    const std::int32_t index = std::int32_t(this->Entries.size());
    this->Entries.push_back(entry);
    for (const std::int32_t s : this->Cluster)
    {
      this->Insert(s, index);
    }
  }

private:
  /// A face that is triangle t alone (Resolve's case without co-circular triangles, and a cluster
  /// of one): labelled t, its points read from t itself (this runs for every face of every tile
  /// derived).
  void ResolveTriangle(std::int32_t t)
  {
    Entry entry;
    entry.Label = t;
    entry.PointStart = OwnTriangle; // (its points in its own order, as a list of them would be)
    entry.PointCount = 3;
    if (this->WantCentres)
    {
      double error = 0.0;
      entry.Centre = FaceCentre(this->T.Points(), this->T.Origin().data() + 3 * t, 3, error);
      entry.Inside = CentreInside(this->T, entry.Label, entry.Centre, error);
    }
    this->Insert(t, std::int32_t(this->Entries.size()));
    this->Entries.push_back(entry);
  }

  // Entry::PointStart of a face that is one triangle: its points are the triangle's (Label's)
  // origins, read in place rather than copied to Points (three appends per face derived).
  static constexpr std::int32_t OwnTriangle = -1;

  // The centre first: 32 bytes without padding inside (40 with the label first), and an update
  // labels some 8500 faces.
  struct Entry
  {
    Point2 Centre;
    std::int32_t Label = -1;
    std::int32_t PointStart = 0;
    std::int32_t PointCount = 0;
    bool Inside = false;
  };

  /// Appends triangle t's three points to Points (push_back: a range insert took a tenth of the
  /// labelling's instructions).
  void AppendPointsOf(std::int32_t t)
  {
    const std::int32_t* v = this->T.Origin().data() + 3 * t;
    this->Points.push_back(v[0]);
    this->Points.push_back(v[1]);
    this->Points.push_back(v[2]);
  }

  /// Entry index of t; -1 when t is not listed, -2 while its cluster is being flooded.
  std::int32_t Find(std::int32_t t) const { return this->EntryOf.Find(t); }
  void Insert(std::int32_t t, std::int32_t value) { this->EntryOf.Set(t, value); }

  const Tess& T;
  const bool WantCentres;
  const bool FreeOfCocircular;
  TriangleEntries EntryOf; // per triangle: entry index, -1 unlisted, -2 pending
  std::vector<Entry> Entries;
  std::vector<std::int32_t> Points; // per entry (but OwnTriangle ones), its face's point ids
  std::vector<std::int32_t> Cluster;
};

// VertexEdges without tracked vertex edges: one pass over the half-edge arrays, stopped once every
// id is found. Appends (id, edge) for each id's first occurrence; ids never found keep edge -1.
void FindVertexEdgesByScan(const Tess& tess,
  const std::vector<std::int32_t>& ids,
  std::vector<std::pair<std::int32_t, std::int32_t>>& found)
{
  std::vector<std::int32_t> slot(tess.PointCount(), -1);
  for (const std::int32_t id : ids)
  {
    if (id >= 0 && std::size_t(id) < tess.PointCount() && slot[id] < 0)
    {
      slot[id] = std::int32_t(found.size());
      found.emplace_back(id, -1);
    }
  }
  std::size_t missing = found.size();
  const auto& org = tess.Origin();
  for (std::size_t e = 0; e < org.size() && missing > 0; ++e)
  {
    const std::int32_t v = org[e];
    if (v >= 0 && slot[v] >= 0 && found[slot[v]].second < 0)
    {
      found[slot[v]].second = std::int32_t(e);
      --missing;
    }
  }
}

// Sets the edge of every later occurrence of an id in ids to -1 (found: an entry per id, in the
// order of ids). Repeats are found by sorting the ids (a table of the points cost O(points) a
// call, however few ids were asked for), unless they strictly ascend: the areal average's updates
// ask for sorted, distinct ids, and sorting them again took 3% of an update's instructions.
void DropLaterRepeats(const std::vector<std::int32_t>& ids,
  std::vector<std::pair<std::int32_t, std::int32_t>>& found)
{
  if (std::adjacent_find(ids.begin(), ids.end(), std::greater_equal<std::int32_t>()) == ids.end())
  {
    return;
  }
  std::vector<std::pair<std::int32_t, std::int32_t>> byId; // (id, its place in found)
  byId.reserve(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k)
  {
    byId.emplace_back(ids[k], std::int32_t(k));
  }
  std::sort(byId.begin(), byId.end());
  for (std::size_t k = 1; k < byId.size(); ++k)
  {
    if (byId[k].first == byId[k - 1].first)
    {
      found[byId[k].second].second = -1; // a later occurrence
    }
  }
}

// For each accepted id (first occurrence), a half-edge leaving it. Returns (id, edge) pairs in the
// order of ids; ids that are not vertices (rejected, duplicate, removed, unknown) are dropped.
// (Status() is not asked: it costs O(removed points) per call.)
std::vector<std::pair<std::int32_t, std::int32_t>> VertexEdges(const Tess& tess,
  const std::vector<std::int32_t>& ids)
{
  std::vector<std::pair<std::int32_t, std::int32_t>> found;
  if (tess.TracksVertexEdges())
  {
    // O(1) per id (-1 for one that is no vertex).
    found.reserve(ids.size());
    for (const std::int32_t id : ids)
    {
      found.emplace_back(id, tess.EdgeLeaving(id));
    }
    DropLaterRepeats(ids, found);
  }
  else
  {
    FindVertexEdgesByScan(tess, ids, found);
  }
  found.erase(std::remove_if(found.begin(),
                found.end(),
                [](const std::pair<std::int32_t, std::int32_t>& f) { return f.second < 0; }),
    found.end());
  return found;
}

void AppendMates(const Tess& tess,
  const LocalFaces& faces,
  std::int32_t v,
  const std::vector<std::int32_t>& ring,
  std::vector<std::int32_t>& scratch,
  FaceMateLists& mates)
{
  scratch.clear();
  const auto& org = tess.Origin();
  for (const std::int32_t e : ring)
  {
    const std::int32_t* begin = nullptr;
    const std::int32_t* end = nullptr;
    faces.FacePoints(e / 3, begin, end);
    scratch.insert(scratch.end(), begin, end);
    if (org[Tess::Next(e)] >= 0)
    {
      scratch.push_back(org[Tess::Next(e)]);
    }
  }
  std::sort(scratch.begin(), scratch.end());
  scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
  mates.PointIds.push_back(v);
  for (const std::int32_t j : scratch)
  {
    if (j != v)
    {
      mates.Ids.push_back(j);
    }
  }
  mates.Offsets.push_back(std::int64_t(mates.Ids.size()));
}

// The collinear case: from the full derivation (no faces; the line is short-lived).
TileSet CollinearTilesOf(const Tess& tess,
  const std::vector<std::int32_t>& ids,
  FaceMateLists* mates)
{
  const TileSet all = TessellationDual(tess).Tiles();
  std::vector<std::int32_t> index(tess.PointCount(), -1);
  for (std::size_t k = 0; k < all.PointIds.size(); ++k)
  {
    index[all.PointIds[k]] = std::int32_t(k);
  }
  const auto& line = tess.CollinearPoints();
  std::vector<std::int32_t> position(tess.PointCount(), -1);
  for (std::size_t k = 0; k < line.size(); ++k)
  {
    position[line[k]] = std::int32_t(k);
  }
  TileSet tiles;
  tiles.Offsets.push_back(0);
  for (const std::int32_t id : ids)
  {
    if (id < 0 || std::size_t(id) >= index.size() || index[id] < 0)
    {
      continue;
    }
    const std::size_t k = std::size_t(index[id]);
    index[id] = -1; // repeats are skipped
    tiles.PointIds.push_back(id);
    tiles.Vertices.insert(tiles.Vertices.end(),
      all.Vertices.begin() + all.Offsets[k],
      all.Vertices.begin() + all.Offsets[k + 1]);
    tiles.Offsets.push_back(std::int64_t(tiles.Vertices.size()));
    tiles.Areas.push_back(all.Areas[k]);
    tiles.NeighborCounts.push_back(all.NeighborCounts[k]);
    if (mates)
    {
      mates->PointIds.push_back(id);
      const std::int32_t p = position[id];
      std::int32_t pair[2] = { p > 0 ? line[p - 1] : -1,
        p + 1 < std::int32_t(line.size()) ? line[p + 1] : -1 };
      std::sort(pair, pair + 2);
      for (const std::int32_t j : pair)
      {
        if (j >= 0)
        {
          mates->Ids.push_back(j);
        }
      }
      mates->Offsets.push_back(std::int64_t(mates->Ids.size()));
    }
  }
  return tiles;
}

// Tiles (when wanted) and mates of starts[begin, end) into tiles and mates (each with its
// leading 0 offset).
void LocalTilesOfRange(const Tess& tess,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& starts,
  std::size_t begin,
  std::size_t end,
  bool wantTiles,
  TileSet& tiles,
  FaceMateLists* mates)
{
  LocalFaces faces(tess, wantTiles, end - begin);
  std::vector<TileEdge> edges;
  std::vector<Point2> polygon;
  std::vector<std::int32_t> ring, scratch;
  for (std::size_t k = begin; k < end; ++k)
  {
    const auto& [v, start] = starts[k];
    // Label the faces of the ring first (the tile edges read them).
    CollectRing(tess, start, ring);
    for (const std::int32_t e : ring)
    {
      faces.Resolve(e / 3);
    }
    if (mates)
    {
      AppendMates(tess, faces, v, ring, scratch, *mates);
    }
    if (!wantTiles)
    {
      continue;
    }
    AppendRingTile(tess, faces, v, ring, edges, polygon, tiles);
  }
}

/// How many rings VisitTilesOfRange walks at once (CollectRingsTogether).
constexpr std::size_t RingsWalkedTogether = 4;

/// The rings (CollectRing) of starts[0, count), count at most RingsWalkedTogether, walked a step
/// of each in turn. A step of a walk loads a twin that the next step needs, so a lone walk waits
/// for each cache miss in turn, where walks taken together wait for theirs at once. (The tiles an
/// update derives lie apart in memory: in the synthetic 100k-gauge stream, walking their rings one
/// at a time was a fifth of this pass; four at once, with the next four's first triangles asked
/// for meanwhile, took 5-10% off the pass.) Each step also asks for its triangle's origins, which
/// the labelling of the ring's faces reads next.
void CollectRingsTogether(const Tess& tess,
  const std::pair<std::int32_t, std::int32_t>* starts,
  std::size_t count,
  std::vector<std::int32_t>* rings)
{
  std::int32_t at[RingsWalkedTogether];
  for (std::size_t i = 0; i < count; ++i)
  {
    rings[i].clear();
    at[i] = starts[i].second;
  }
  const std::int32_t* const origins = tess.Origin().data();
  for (std::size_t left = count; left > 0;)
  {
    for (std::size_t i = 0; i < count; ++i)
    {
      const std::int32_t e = at[i];
      if (e < 0)
      {
        continue; // (this ring is closed)
      }
      rings[i].push_back(e);
      __builtin_prefetch(origins + (e - e % 3));
      at[i] = tess.RingNext(e);
      if (at[i] == starts[i].second)
      {
        at[i] = -1;
        --left;
      }
    }
  }
}

/// Asks for the first triangles of starts[0, count)'s rings and their points' coordinates, so
/// that they are on their way while the rings before them are labelled and visited.
void PrefetchRingStarts(const Tess& tess,
  const std::pair<std::int32_t, std::int32_t>* starts,
  std::size_t count)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    const auto& [v, e] = starts[i];
    __builtin_prefetch(tess.Origin().data() + (e - e % 3));
    __builtin_prefetch(tess.Twin().data() + (e - e % 3));
    __builtin_prefetch(tess.Points().data() + v);
  }
}

// Visits the tiles of starts[begin, end) as they are made (VisitTilesOf's chunk), their rings
// walked RingsWalkedTogether at a time while the next ones' starts are fetched.
void VisitTilesOfRange(const Tess& tess,
  const std::vector<std::pair<std::int32_t, std::int32_t>>& starts,
  std::size_t begin,
  std::size_t end,
  std::size_t chunk,
  const TileVisitor& visit,
  std::vector<std::int32_t>* table)
{
  LocalFaces faces(tess, true, end - begin, table);
  std::vector<TileEdge> edges;
  std::vector<Point2> polygon;
  std::vector<std::int32_t> rings[RingsWalkedTogether];
  for (std::size_t k = begin; k < end; k += RingsWalkedTogether)
  {
    const std::size_t count = std::min(RingsWalkedTogether, end - k);
    CollectRingsTogether(tess, starts.data() + k, count, rings);
    const std::size_t next = k + count;
    PrefetchRingStarts(tess, starts.data() + next, std::min(RingsWalkedTogether, end - next));
    for (std::size_t i = 0; i < count; ++i)
    {
      const std::int32_t v = starts[k + i].first;
      for (const std::int32_t e : rings[i])
      {
        faces.Resolve(e / 3);
      }
      bool interior = false;
      RingTilePolygon(tess, faces, v, rings[i], edges, polygon, interior);
      visit(chunk, v, polygon.data(), polygon.size());
    }
  }
}

// VisitTilesOf's chunk bounds for n starts when the calling thread's chunk 0 takes callerWeight
// tiles per tile of each other chunk; the others share the rest equally.
std::vector<std::int32_t> WeightedChunkBounds(std::int32_t n,
  std::size_t chunks,
  double callerWeight)
{
  const double total = callerWeight + double(chunks - 1);
  const auto first = std::int32_t(std::clamp(std::round(n * callerWeight / total), 0.0, double(n)));
  std::vector<std::int32_t> bounds{ 0 };
  for (const std::int32_t b : parallel::ChunkBounds(n - first, chunks - 1))
  {
    bounds.push_back(first + b);
  }
  return bounds;
}

// The calling thread's weight for the next call, from when the chunks of this one ended (chunk k
// visited bounds[k] .. bounds[k + 1]). It derives the tiles near the triangles it has just
// written, from its own cache, while another thread reads them from memory and starts later
// (the areal average's updates: the other chunk ended 40 to 100 us after the caller's, of some
// 600). Each chunk's time per tile gives the weight that would have ended them together (within
// 1/2 .. 2); the weight moves a quarter of the way there, so that one chunk held up by the machine
// (a worker that ended 1.2 ms late) does not unbalance the next calls, and stays where chunks are
// too small to time.
double AdaptedCallerWeight(double weight,
  const std::vector<std::int32_t>& bounds,
  const std::vector<double>& ends)
{
  constexpr std::int32_t FewestTimed = 64;
  const std::size_t chunks = bounds.size() - 1;
  const auto tilesOf = [&bounds](std::size_t k) { return double(bounds[k + 1] - bounds[k]); };
  for (std::size_t k = 0; k < chunks; ++k)
  {
    if (tilesOf(k) < FewestTimed || !(ends[k] > 0.0))
    {
      return weight;
    }
  }
  double others = 0.0; // the other chunks' mean time per tile
  for (std::size_t k = 1; k < chunks; ++k)
  {
    others += ends[k] / tilesOf(k) / double(chunks - 1);
  }
  const double caller = ends[0] / tilesOf(0);
  return 0.75 * weight + 0.25 * std::clamp(others / caller, 0.5, 2.0);
}

template<class T>
void Append(std::vector<T>& to, const std::vector<T>& from)
{
  to.insert(to.end(), from.begin(), from.end());
}

/// Appends offsets[1..] shifted by base (the size of what they index, before appending).
void AppendOffsets(std::vector<std::int64_t>& to,
  const std::vector<std::int64_t>& from,
  std::int64_t base)
{
  for (std::size_t k = 1; k < from.size(); ++k)
  {
    to.push_back(base + from[k]);
  }
}

TileSet LocalTiles(const Tess& tess,
  const std::vector<std::int32_t>& ids,
  bool wantTiles,
  FaceMateLists* mates)
{
  if (mates)
  {
    *mates = FaceMateLists();
    mates->Offsets.push_back(0);
  }
  if (!tess.IsTwoDimensional())
  {
    return CollinearTilesOf(tess, ids, mates);
  }
  TileSet tiles;
  tiles.Offsets.push_back(0);
  if (ids.empty())
  {
    return tiles; // without the O(points) and O(triangles) tables below
  }
  const std::vector<std::pair<std::int32_t, std::int32_t>> starts = VertexEdges(tess, ids);
  // Chunks of the points on the cores (each labels the faces it meets on its own, with the same
  // rules, so the joined result is the serial one). A local tile or mate list costs about 1 us
  // (it misses the cache where the full derivation streams), hence the small minimum per thread:
  // the face mates of 500 points among 100k took 0.50 ms on two threads against 0.70 on one.
  const std::vector<std::int32_t> bounds =
    parallel::ChunkBounds(std::int32_t(starts.size()), parallel::ThreadCount(starts.size(), 250));
  const std::size_t chunks = bounds.size() - 1;
  // Each chunk's results, chunk 0's too, on cache lines of their own (cache_line.h): a chunk
  // writes its vectors' ends at every tile.
  std::vector<OwnCacheLines<TileSet>> partTiles(chunks);
  std::vector<OwnCacheLines<FaceMateLists>> partMates(mates ? chunks : 0);
  parallel::RunChunks(chunks,
    [&](std::size_t k)
    {
      TileSet& out = partTiles[k].Value;
      FaceMateLists* outMates = mates ? &partMates[k].Value : nullptr;
      out.Offsets.push_back(0);
      if (outMates)
      {
        outMates->Offsets.push_back(0);
      }
      LocalTilesOfRange(tess, starts, bounds[k], bounds[k + 1], wantTiles, out, outMates);
    });
  if (mates)
  {
    *mates = std::move(partMates[0].Value);
    for (std::size_t k = 1; k < chunks; ++k)
    {
      const FaceMateLists& part = partMates[k].Value;
      Append(mates->PointIds, part.PointIds);
      AppendOffsets(mates->Offsets, part.Offsets, std::int64_t(mates->Ids.size()));
      Append(mates->Ids, part.Ids);
    }
  }
  return JoinTileParts(partTiles);
}

} // namespace

TileSet ComputeTilesOf(const DirichletTessellation& tessellation,
  const std::vector<std::int32_t>& ids,
  FaceMateLists* mates)
{
  CheckWindowInExactRange(tessellation);
  return LocalTiles(tessellation, ids, true, mates);
}

std::size_t VisitTilesOf(const DirichletTessellation& tessellation,
  const std::vector<std::int32_t>& ids,
  std::size_t maxChunks,
  std::int64_t minimumPerThread,
  const TileVisitor& visit,
  LocalTilesWorkspace* workspace)
{
  CheckWindowInExactRange(tessellation);
  if (!tessellation.IsTwoDimensional())
  {
    const TileSet tiles = CollinearTilesOf(tessellation, ids, nullptr);
    for (std::size_t k = 0; k < tiles.PointIds.size(); ++k)
    {
      visit(0,
        tiles.PointIds[k],
        &tiles.Vertices[tiles.Offsets[k]],
        std::size_t(tiles.Offsets[k + 1] - tiles.Offsets[k]));
    }
    return tiles.PointIds.size();
  }
  if (ids.empty())
  {
    return 0;
  }
  const std::vector<std::pair<std::int32_t, std::int32_t>> starts = VertexEdges(tessellation, ids);
  const std::size_t chunks = std::max<std::size_t>(
    1, std::min(maxChunks, parallel::ThreadCount(std::int64_t(starts.size()), minimumPerThread)));
  const auto n = std::int32_t(starts.size());
  const std::vector<std::int32_t> bounds = workspace && chunks > 1
    ? WeightedChunkBounds(n, chunks, workspace->CallerWeight)
    : parallel::ChunkBounds(n, chunks);
  if (workspace)
  {
    workspace->FaceTables.resize(std::max(workspace->FaceTables.size(), chunks));
  }
  // Per chunk, when it ended, in seconds from the start (AdaptedCallerWeight's).
  std::vector<double> ends(workspace ? chunks : 0, 0.0);
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  parallel::RunChunks(chunks,
    [&](std::size_t k)
    {
      VisitTilesOfRange(tessellation,
        starts,
        bounds[k],
        bounds[k + 1],
        k,
        visit,
        workspace ? &workspace->FaceTables[k] : nullptr);
      if (workspace)
      {
        ends[k] = std::chrono::duration<double>(Clock::now() - start).count();
      }
    });
  if (workspace && chunks > 1)
  {
    workspace->CallerWeight = AdaptedCallerWeight(workspace->CallerWeight, bounds, ends);
  }
  return starts.size();
}

FaceMateLists ComputeFaceMatesOf(const DirichletTessellation& tessellation,
  const std::vector<std::int32_t>& ids)
{
  FaceMateLists mates;
  LocalTiles(tessellation, ids, false, &mates);
  return mates;
}

} // namespace tessera
