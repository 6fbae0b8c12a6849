#include "ridge_contours.h"

#include "errors.h"
#include "ridge_extraction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>

namespace tessera
{

namespace
{

bool Inside(int i, int j, int width, int height)
{
  return i >= 0 && j >= 0 && i < width && j < height;
}

bool MaskAt(const std::vector<std::uint8_t>& mask, int width, int height, int i, int j)
{
  return Inside(i, j, width, height) && mask[static_cast<std::size_t>(j) * width + i] != 0;
}

int NeighbourCount(const std::vector<std::uint8_t>& mask, int width, int height, int i, int j)
{
  int count = 0;
  for (int k = 0; k < 8; ++k)
  {
    count += MaskAt(mask, width, height, i + NeighbourDx[k], j + NeighbourDy[k]) ? 1 : 0;
  }
  return count;
}

} // namespace

double StepLength(int a, int b, int width)
{
  const double dx = (a % width) - (b % width);
  const double dy = (a / width) - (b / width);
  return std::sqrt(dx * dx + dy * dy);
}

namespace
{

double PathLength(const std::vector<int>& pixels, int begin, int end, bool closed, int width)
{
  double length = 0.0;
  for (int k = begin + 1; k < end; ++k)
  {
    length += StepLength(pixels[k - 1], pixels[k], width);
  }
  if (closed && end - begin > 1)
  {
    length += StepLength(pixels[end - 1], pixels[begin], width);
  }
  return length;
}

// A minor-ridge segment: a run of pixels in SegmentPixels[First, Last) and, at each end, the
// branch pixel it touches (-1 for a free end) and that pixel's junction.
struct Segment
{
  int First = 0;
  int Last = 0;
  int Attach[2] = { -1, -1 };
  int Junction[2] = { -1, -1 };
  bool Loop = false;
  bool HasMajor = false;
  double Length = 0.0;
};

// The skeleton as a graph of segments and junctions, all in flat arrays indexed by pixel.
class SkeletonGraph
{
public:
  SkeletonGraph(const std::vector<std::uint8_t>& skeleton, int width, int height)
    : Skeleton(skeleton)
    , Width(width)
    , Height(height)
    , IsBranch(skeleton.size(), 0)
    , JunctionOf(skeleton.size(), -1)
    , Visited(skeleton.size(), 0)
  {
    for (std::size_t p = 0; p < skeleton.size(); ++p)
    {
      if (skeleton[p])
      {
        this->SkeletonPixels.push_back(static_cast<int>(p));
      }
    }
    this->MarkBranchPixels();
    this->LabelJunctions();
    this->WalkAllSegments();
  }

  std::vector<Segment> Segments;
  std::vector<int> SegmentPixels;
  int BranchPixelCount = 0;
  int JunctionCount = 0;

private:
  template<typename Visit>
  void ForEachNeighbour(int p, Visit visit) const
  {
    const int i = p % this->Width;
    const int j = p / this->Width;
    for (int k = 0; k < 8; ++k)
    {
      const int ni = i + NeighbourDx[k];
      const int nj = j + NeighbourDy[k];
      if (MaskAt(this->Skeleton, this->Width, this->Height, ni, nj))
      {
        visit(nj * this->Width + ni);
      }
    }
  }

  void MarkBranchPixels()
  {
    for (int p : this->SkeletonPixels)
    {
      int degree = 0;
      this->ForEachNeighbour(p, [&](int) { ++degree; });
      if (degree >= 3)
      {
        this->IsBranch[p] = 1;
        ++this->BranchPixelCount;
      }
    }
  }

  // Adjacent branch pixels are one junction: a crossing often thins to a small cluster.
  void LabelJunctions()
  {
    std::vector<int> stack;
    for (int p : this->SkeletonPixels)
    {
      if (!this->IsBranch[p] || this->JunctionOf[p] >= 0)
      {
        continue;
      }
      const int label = this->JunctionCount++;
      this->JunctionOf[p] = label;
      stack.push_back(p);
      while (!stack.empty())
      {
        const int q = stack.back();
        stack.pop_back();
        this->ForEachNeighbour(q,
          [&](int n)
          {
            if (this->IsBranch[n] && this->JunctionOf[n] < 0)
            {
              this->JunctionOf[n] = label;
              stack.push_back(n);
            }
          });
      }
    }
  }

  int OrdinaryNeighbourCount(int p) const
  {
    int count = 0;
    this->ForEachNeighbour(p, [&](int n) { count += this->IsBranch[n] ? 0 : 1; });
    return count;
  }

  void WalkAllSegments()
  {
    // Runs with an end (an end pixel or a pixel next to a junction) first; what is left after
    // that are closed loops without any junction.
    for (int p : this->SkeletonPixels)
    {
      if (!this->IsBranch[p] && !this->Visited[p] && this->OrdinaryNeighbourCount(p) <= 1)
      {
        this->WalkSegment(p, false);
      }
    }
    for (int p : this->SkeletonPixels)
    {
      if (!this->IsBranch[p] && !this->Visited[p])
      {
        this->WalkSegment(p, true);
      }
    }
  }

  void WalkSegment(int start, bool loop)
  {
    Segment segment;
    segment.Loop = loop;
    segment.First = static_cast<int>(this->SegmentPixels.size());
    int previous = -1;
    int current = start;
    while (current >= 0)
    {
      this->Visited[current] = 1;
      this->SegmentPixels.push_back(current);
      int next = -1;
      this->ForEachNeighbour(current,
        [&](int n)
        {
          if (next < 0 && !this->IsBranch[n] && n != previous && !this->Visited[n])
          {
            next = n;
          }
        });
      previous = current;
      current = next;
    }
    segment.Last = static_cast<int>(this->SegmentPixels.size());
    if (!loop)
    {
      this->AttachEnds(segment);
    }
    segment.Length =
      PathLength(this->SegmentPixels, segment.First, segment.Last, loop, this->Width);
    this->Segments.push_back(segment);
  }

  void AttachEnds(Segment& segment) const
  {
    std::vector<int> atStart;
    this->ForEachNeighbour(this->SegmentPixels[segment.First],
      [&](int n)
      {
        if (this->IsBranch[n])
        {
          atStart.push_back(n);
        }
      });
    std::vector<int> atEnd;
    this->ForEachNeighbour(this->SegmentPixels[segment.Last - 1],
      [&](int n)
      {
        if (this->IsBranch[n])
        {
          atEnd.push_back(n);
        }
      });
    if (!atStart.empty())
    {
      segment.Attach[0] = atStart[0];
    }
    // A one-pixel run touches its junctions at both ends with the same pixel: give its second
    // end a different branch pixel, if it has one.
    for (int candidate : atEnd)
    {
      if (segment.Last - segment.First > 1 || candidate != segment.Attach[0])
      {
        segment.Attach[1] = candidate;
        break;
      }
    }
    for (int side = 0; side < 2; ++side)
    {
      if (segment.Attach[side] >= 0)
      {
        segment.Junction[side] = this->JunctionOf[segment.Attach[side]];
      }
    }
  }

  const std::vector<std::uint8_t>& Skeleton;
  int Width;
  int Height;
  std::vector<int> SkeletonPixels;
  std::vector<std::uint8_t> IsBranch;
  std::vector<int> JunctionOf;
  std::vector<std::uint8_t> Visited;
};

// Union-find over segments, carrying the length of the contour each chain forms so far.
class ChainSet
{
public:
  explicit ChainSet(const std::vector<Segment>& segments)
    : Parent(segments.size())
    , ChainLength(segments.size())
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
      this->ChainLength[s] = segments[s].Length;
    }
  }
  int Find(int s)
  {
    while (this->Parent[s] != s)
    {
      this->Parent[s] = this->Parent[this->Parent[s]];
      s = this->Parent[s];
    }
    return s;
  }
  double Length(int s) { return this->ChainLength[this->Find(s)]; }
  void Join(int a, int b, double bridge)
  {
    const int ra = this->Find(a);
    const int rb = this->Find(b);
    if (ra == rb)
    {
      this->ChainLength[ra] += bridge;
      return;
    }
    this->Parent[rb] = ra;
    this->ChainLength[ra] += this->ChainLength[rb] + bridge;
  }

private:
  std::vector<int> Parent;
  std::vector<double> ChainLength;
};

// Segment ends are numbered 2 * segment + side (side 0 = first pixel, 1 = last pixel).
class Joiner
{
public:
  Joiner(const std::vector<Segment>& segments,
    const std::vector<int>& pixels,
    int width,
    const RidgeContourSettings& settings,
    int junctionCount)
    : Segments(segments)
    , Pixels(pixels)
    , Width(width)
    , Settings(settings)
    , Link(2 * segments.size(), -1)
    , EndsAt(junctionCount)
  {
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
      for (int side = 0; side < 2; ++side)
      {
        if (segments[s].Junction[side] >= 0)
        {
          this->EndsAt[segments[s].Junction[side]].push_back(static_cast<int>(2 * s) + side);
        }
      }
    }
  }

  std::vector<int> JoinAll()
  {
    ChainSet chains(this->Segments);
    for (int junction : this->JunctionsLongestFirst())
    {
      this->JoinAtJunction(junction, chains);
    }
    return this->Link;
  }

private:
  // Junctions on long segments decide first, so a long ridge is not cut by a decision made
  // at a junction among short noise branches.
  std::vector<int> JunctionsLongestFirst() const
  {
    std::vector<double> longest(this->EndsAt.size(), 0.0);
    for (std::size_t junction = 0; junction < this->EndsAt.size(); ++junction)
    {
      for (int end : this->EndsAt[junction])
      {
        longest[junction] = std::max(longest[junction], this->Segments[end / 2].Length);
      }
    }
    std::vector<int> order(this->EndsAt.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(
      order.begin(), order.end(), [&](int a, int b) { return longest[a] > longest[b]; });
    return order;
  }

  void JoinAtJunction(int junction, ChainSet& chains)
  {
    for (;;)
    {
      std::vector<int> open;
      for (int end : this->EndsAt[junction])
      {
        if (this->Link[end] < 0)
        {
          open.push_back(end);
        }
      }
      if (open.size() < 2)
      {
        return;
      }
      this->PreferMeasurableTangents(open, chains);
      int bestA = -1;
      int bestB = -1;
      double bestScore = -std::numeric_limits<double>::infinity();
      for (std::size_t a = 0; a < open.size(); ++a)
      {
        for (std::size_t b = a + 1; b < open.size(); ++b)
        {
          const double score = this->PairScore(open[a], open[b], chains);
          if (score > bestScore)
          {
            bestScore = score;
            bestA = open[a];
            bestB = open[b];
          }
        }
      }
      this->Link[bestA] = bestB;
      this->Link[bestB] = bestA;
      chains.Join(bestA / 2, bestB / 2, this->BridgeLength(bestA, bestB));
    }
  }

  // The tangent of a stub one or two pixels long points in an arbitrary chain-code direction
  // and would often look like the straight continuation of a ridge: under the tangent rule,
  // ends whose chains are shorter than the tangent length only pair among themselves, after
  // the others.
  void PreferMeasurableTangents(std::vector<int>& open, ChainSet& chains) const
  {
    if (this->Settings.Join != JoinRule::ClosestTangent)
    {
      return;
    }
    std::vector<int> measurable;
    for (int end : open)
    {
      if (chains.Length(end / 2) >= this->Settings.TangentPixels)
      {
        measurable.push_back(end);
      }
    }
    if (measurable.size() >= 2)
    {
      open.swap(measurable);
    }
  }

  double PairScore(int a, int b, ChainSet& chains) const
  {
    if (this->Settings.Join == JoinRule::ClosestTangent)
    {
      double ax = 0.0;
      double ay = 0.0;
      double bx = 0.0;
      double by = 0.0;
      this->Tangent(a, ax, ay);
      this->Tangent(b, bx, by);
      return -(ax * bx + ay * by); // most nearly opposite directions away from the junction
    }
    // Closing a chain into a ring scores as the ring traced twice: it wins over extending the
    // chain by a branch unless that branch is longer than the whole ring.
    const bool sameChain = chains.Find(a / 2) == chains.Find(b / 2);
    return sameChain ? 2.0 * chains.Length(a / 2) : chains.Length(a / 2) + chains.Length(b / 2);
  }

  // Unit direction from the junction pixel into the segment, over TangentPixels pixels.
  void Tangent(int end, double& tx, double& ty) const
  {
    const Segment& s = this->Segments[end / 2];
    const int count = s.Last - s.First;
    const int steps = std::min(this->Settings.TangentPixels, count - 1);
    const int inner =
      (end % 2 == 0) ? this->Pixels[s.First + steps] : this->Pixels[s.Last - 1 - steps];
    const int origin = s.Attach[end % 2];
    tx = (inner % this->Width) - (origin % this->Width);
    ty = (inner / this->Width) - (origin / this->Width);
    const double norm = std::hypot(tx, ty);
    if (norm > 0.0)
    {
      tx /= norm;
      ty /= norm;
    }
  }

  double BridgeLength(int a, int b) const
  {
    const Segment& sa = this->Segments[a / 2];
    const Segment& sb = this->Segments[b / 2];
    const int endA = (a % 2 == 0) ? this->Pixels[sa.First] : this->Pixels[sa.Last - 1];
    const int endB = (b % 2 == 0) ? this->Pixels[sb.First] : this->Pixels[sb.Last - 1];
    const int attachA = sa.Attach[a % 2];
    const int attachB = sb.Attach[b % 2];
    return StepLength(endA, attachA, this->Width) + StepLength(attachA, attachB, this->Width) +
      StepLength(attachB, endB, this->Width);
  }

  const std::vector<Segment>& Segments;
  const std::vector<int>& Pixels;
  int Width;
  const RidgeContourSettings& Settings;
  std::vector<int> Link;
  std::vector<std::vector<int>> EndsAt;
};

// Follows the links from segment to segment, writing each contour's pixels.
class ContourTracer
{
public:
  ContourTracer(const std::vector<Segment>& segments,
    const std::vector<int>& pixels,
    const std::vector<int>& link)
    : Segments(segments)
    , Pixels(pixels)
    , Link(link)
    , Done(segments.size(), 0)
  {
  }

  void TraceAll(std::vector<std::vector<int>>& contours, std::vector<std::uint8_t>& closed)
  {
    for (std::size_t s = 0; s < this->Segments.size(); ++s)
    {
      for (int side = 0; side < 2 && !this->Done[s] && !this->Segments[s].Loop; ++side)
      {
        if (this->Link[2 * s + side] < 0)
        {
          contours.push_back(this->Trace(static_cast<int>(s), side));
          closed.push_back(0);
        }
      }
    }
    // Everything left is on a cycle: a loop segment or segments joined into a ring.
    for (std::size_t s = 0; s < this->Segments.size(); ++s)
    {
      if (!this->Done[s])
      {
        contours.push_back(this->Trace(static_cast<int>(s), 0));
        closed.push_back(1);
      }
    }
  }

private:
  std::vector<int> Trace(int segment, int enterSide)
  {
    std::vector<int> contour;
    const int start = segment;
    for (;;)
    {
      this->Done[segment] = 1;
      this->AppendSegment(segment, enterSide == 0, contour);
      const int exitEnd = 2 * segment + (1 - enterSide);
      const int next = this->Link[exitEnd];
      if (next < 0 || this->Segments[segment].Loop)
      {
        break;
      }
      this->AppendBridge(exitEnd, next, contour);
      segment = next / 2;
      enterSide = next % 2;
      if (segment == start && this->Done[segment])
      {
        break; // back where the ring started
      }
    }
    return contour;
  }

  void AppendSegment(int segment, bool forward, std::vector<int>& contour) const
  {
    const Segment& s = this->Segments[segment];
    if (forward)
    {
      contour.insert(contour.end(), this->Pixels.begin() + s.First, this->Pixels.begin() + s.Last);
    }
    else
    {
      for (int k = s.Last - 1; k >= s.First; --k)
      {
        contour.push_back(this->Pixels[k]);
      }
    }
  }

  void AppendBridge(int exitEnd, int entryEnd, std::vector<int>& contour) const
  {
    const int a = this->Segments[exitEnd / 2].Attach[exitEnd % 2];
    const int b = this->Segments[entryEnd / 2].Attach[entryEnd % 2];
    contour.push_back(a);
    if (b != a)
    {
      contour.push_back(b);
    }
  }

  const std::vector<Segment>& Segments;
  const std::vector<int>& Pixels;
  const std::vector<int>& Link;
  std::vector<std::uint8_t> Done;
};

void CheckMask(const std::vector<std::uint8_t>& mask, int width, int height, const char* name)
{
  if (width < 1 || height < 1 ||
    mask.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
  {
    throw InputError(std::string(name) + " mask of " + std::to_string(mask.size()) +
      " pixels does not match " + std::to_string(width) + " x " + std::to_string(height));
  }
}

bool HasMajorPixel(const Segment& s,
  const std::vector<int>& pixels,
  const std::vector<std::uint8_t>& major)
{
  for (int k = s.First; k < s.Last; ++k)
  {
    if (major[pixels[k]])
    {
      return true;
    }
  }
  return false;
}

/// A saddle path's field falls below this fraction of its ends'. Along a crest, even a noisy one
/// between noise branches, the lowest field of a piece between two junctions was 0.39 of its ends'
/// or more (every test's and example's); across the gap between two curves 5 to 10 widths apart
/// it was 0.08 and less.
constexpr double SaddleDip = 0.25;

/// Whether the field along segment s falls below SaddleDip of the lower of its two end pixels'.
bool DipsDeep(const Segment& s, const std::vector<int>& pixels, const std::vector<double>& field)
{
  const double ends = std::min(field[pixels[s.First]], field[pixels[s.Last - 1]]);
  double lowest = ends;
  for (int k = s.First; k < s.Last; ++k)
  {
    lowest = std::min(lowest, field[pixels[k]]);
  }
  return lowest < SaddleDip * ends;
}

// Step 3 of the header comment. Removing a branch can merge the two segments on either side of
// its branch pixel into one (the pixel then has two neighbours), so the graph is rebuilt after
// each round. Two kinds of segment without a major-ridge pixel go, in this order:
// - dangling ones (a free end) and loops from a junction back to itself, round after round
//   until none is left;
// - only then, segments between two different junctions longer than maximumBridgeLength.
// The order matters: on a noisy crest, major pixels are sparse (ridge_extraction.h) and noise
// branches leave the crest at junctions; once the branches are gone those junctions dissolve
// and the crest pieces between them merge into segments that do have major pixels. Removing
// junction-to-junction pieces in the same round as the branches would cut such a crest. What
// is left between two lasting junctions is a short piece where ridges cross (kept) or a saddle
// path from one ridge across to another (removed: it would join two curves into one group).
// Given the field, a path between two junctions whose field dips deep (DipsDeep) is a saddle path
// at once, removed with the first round's branches: where the ridges' ends beyond its junctions
// had no major pixel, they went first, the junctions dissolved, the path merged with the ridges'
// segments, which have major pixels, and two lines 10 widths apart came out one U-shaped group.
//
//     ridge 1  ====J1======          a saddle path J1 - J2 between two ridges: both junctions
//                  |                 last (each ridge passes through its own), the path has
//                  | saddle path     no major pixel, and it goes
//     ridge 2  ====J2======
SkeletonGraph PruneSegmentsWithoutMajorRidge(std::vector<std::uint8_t>& skeleton,
  const std::vector<std::uint8_t>& major,
  int width,
  int height,
  double maximumBridgeLength,
  const std::vector<double>* field,
  RidgeContours& diagnostics)
{
  bool first = true;
  for (;;)
  {
    SkeletonGraph graph(skeleton, width, height);
    if (first)
    {
      diagnostics.BranchPixelCount = graph.BranchPixelCount;
      diagnostics.SegmentCount = static_cast<int>(graph.Segments.size());
      first = false;
    }
    std::vector<const Segment*> branches, saddlePaths;
    for (const Segment& s : graph.Segments)
    {
      if (HasMajorPixel(s, graph.SegmentPixels, major))
      {
        continue;
      }
      const bool betweenJunctions =
        s.Junction[0] >= 0 && s.Junction[1] >= 0 && s.Junction[0] != s.Junction[1];
      if (!betweenJunctions)
      {
        branches.push_back(&s);
      }
      else if (s.Length > maximumBridgeLength)
      {
        const bool deep = field && DipsDeep(s, graph.SegmentPixels, *field);
        (deep ? branches : saddlePaths).push_back(&s);
      }
    }
    const std::vector<const Segment*>& removal = branches.empty() ? saddlePaths : branches;
    if (removal.empty())
    {
      return graph;
    }
    for (const Segment* s : removal)
    {
      for (int k = s->First; k < s->Last; ++k)
      {
        skeleton[graph.SegmentPixels[k]] = 0;
      }
    }
  }
}

/// Pixels of the contours kept so far, bucketed in square cells of the distance asked about, so
/// that whether a pixel lies within that distance of one of them looks at 3 x 3 cells. (The cell
/// is clamped to 2^24 pixels, so that a huge distance does not overflow its int; pixels further
/// apart than that are far beyond any distance a grouping asks about.)
class PixelBuckets
{
public:
  PixelBuckets(int width, double distance)
    : Width(width)
    , Distance(distance)
    , Cell(static_cast<int>(std::clamp(std::ceil(distance), 1.0, double(1 << 24))))
  {
  }

  void Add(const std::vector<int>& pixels)
  {
    for (int p : pixels)
    {
      this->Cells[this->Key(this->CellI(p), this->CellJ(p))].push_back(p);
    }
  }

  bool Near(int p) const
  {
    for (int a = this->CellI(p) - 1; a <= this->CellI(p) + 1; ++a)
    {
      for (int b = this->CellJ(p) - 1; b <= this->CellJ(p) + 1; ++b)
      {
        const auto cell = this->Cells.find(this->Key(a, b));
        if (cell != this->Cells.end() &&
          std::any_of(cell->second.begin(),
            cell->second.end(),
            [&](int q) { return StepLength(p, q, this->Width) <= this->Distance; }))
        {
          return true;
        }
      }
    }
    return false;
  }

private:
  // (cells from -1 on: Near looks one cell beyond the image's first)
  int CellI(int p) const { return p % this->Width / this->Cell; }
  int CellJ(int p) const { return p / this->Width / this->Cell; }
  static std::int64_t Key(int a, int b) { return (std::int64_t(a + 1) << 32) + (b + 1); }

  int Width;
  double Distance;
  int Cell;
  std::unordered_map<std::int64_t, std::vector<int>> Cells;
};

/// Step 5's side strands: clears keep for each open contour (kept so far, no longer than
/// MaximumSideStrandLength) whose every pixel lies within SideStrandDistance of a pixel of the
/// contours kept before it, taken longest first (of equal lengths, in their order); returns how
/// many. Its points then join those contours, the nearest.
int DropSideStrands(const std::vector<std::vector<int>>& contours,
  const std::vector<std::uint8_t>& closed,
  const std::vector<double>& lengths,
  int width,
  const RidgeContourSettings& settings,
  std::vector<std::uint8_t>& keep)
{
  if (settings.SideStrandDistance == 0.0)
  {
    return 0;
  }
  std::vector<int> order(contours.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(
    order.begin(), order.end(), [&](int a, int b) { return lengths[a] > lengths[b]; });
  PixelBuckets longer(width, settings.SideStrandDistance);
  int dropped = 0;
  for (int c : order)
  {
    const std::vector<int>& pixels = contours[c];
    if (keep[c] && !closed[c] && lengths[c] <= settings.MaximumSideStrandLength &&
      std::all_of(pixels.begin(), pixels.end(), [&](int p) { return longer.Near(p); }))
    {
      keep[c] = 0;
      ++dropped;
    }
    else if (keep[c])
    {
      longer.Add(pixels);
    }
  }
  return dropped;
}

/// Step 5's choice of contours: their lengths, and which are kept (not too short, not a side
/// strand), counting those dropped in diagnostics.
std::vector<std::uint8_t> ContoursToKeep(const std::vector<std::vector<int>>& contours,
  const std::vector<std::uint8_t>& closed,
  int width,
  const RidgeContourSettings& settings,
  std::vector<double>& lengths,
  RidgeContours& diagnostics)
{
  lengths.resize(contours.size());
  std::vector<std::uint8_t> keep(contours.size(), 0);
  for (std::size_t c = 0; c < contours.size(); ++c)
  {
    const std::vector<int>& pixels = contours[c];
    lengths[c] = PathLength(pixels, 0, static_cast<int>(pixels.size()), closed[c] != 0, width);
    if (lengths[c] < settings.MinimumLength)
    {
      ++diagnostics.ShortContourCount;
    }
    else if (closed[c] && lengths[c] < settings.MinimumLoopLength)
    {
      ++diagnostics.ShortLoopCount;
    }
    else
    {
      keep[c] = 1;
    }
  }
  diagnostics.SideStrandCount = DropSideStrands(contours, closed, lengths, width, settings, keep);
  return keep;
}

} // namespace

int ConnectivityNumber(const std::vector<std::uint8_t>& mask, int width, int height, int i, int j)
{
  int background[8];
  for (int k = 0; k < 8; ++k)
  {
    background[k] = MaskAt(mask, width, height, i + NeighbourDx[k], j + NeighbourDy[k]) ? 0 : 1;
  }
  int number = 0;
  for (int k = 0; k < 8; k += 2)
  {
    number += background[k] - background[k] * background[(k + 1) % 8] * background[(k + 2) % 8];
  }
  return number;
}

void ThinToSkeleton(std::vector<std::uint8_t>& mask, int width, int height)
{
  CheckMask(mask, width, height, "thinning");
  std::vector<int> candidates;
  for (std::size_t p = 0; p < mask.size(); ++p)
  {
    if (mask[p])
    {
      candidates.push_back(static_cast<int>(p));
    }
  }
  // Directions N, S, E, W: a pixel is peeled only from a border facing that way.
  const int borderDirections[4] = { 2, 6, 0, 4 };
  bool changed = true;
  while (changed)
  {
    changed = false;
    for (int direction : borderDirections)
    {
      for (int p : candidates)
      {
        const int i = p % width;
        const int j = p / width;
        if (!mask[p] ||
          MaskAt(mask, width, height, i + NeighbourDx[direction], j + NeighbourDy[direction]))
        {
          continue;
        }
        if (NeighbourCount(mask, width, height, i, j) >= 2 &&
          ConnectivityNumber(mask, width, height, i, j) == 1)
        {
          mask[p] = 0;
          changed = true;
        }
      }
    }
    candidates.erase(
      std::remove_if(candidates.begin(), candidates.end(), [&](int p) { return mask[p] == 0; }),
      candidates.end());
  }
}

RidgeContours TraceRidgeContours(const std::vector<std::uint8_t>& minor,
  const std::vector<std::uint8_t>& major,
  int width,
  int height,
  const RidgeContourSettings& settings,
  const std::vector<double>* field)
{
  CheckMask(minor, width, height, "minor ridge");
  CheckMask(major, width, height, "major ridge");
  if (field && field->size() != minor.size())
  {
    throw InputError("field of " + std::to_string(field->size()) + " values for a " +
      std::to_string(width) + " x " + std::to_string(height) + " image");
  }
  for (const auto& [what, value] :
    { std::make_pair("minimum contour length", settings.MinimumLength),
      std::make_pair("minimum loop length", settings.MinimumLoopLength),
      std::make_pair("side strand distance", settings.SideStrandDistance),
      std::make_pair("maximum side strand length", settings.MaximumSideStrandLength),
      std::make_pair("maximum bridge length", settings.MaximumBridgeLength) })
  {
    if (!(value >= 0.0) || !std::isfinite(value))
    {
      throw InputError(
        std::string(what) + " " + NumberText(value) + " is not a finite non-negative number");
    }
  }
  if (settings.TangentPixels < 1)
  {
    throw InputError(
      "tangent length " + std::to_string(settings.TangentPixels) + " pixels is below 1");
  }
  RidgeContours result;
  result.Skeleton = minor;
  ThinToSkeleton(result.Skeleton, width, height);
  std::vector<std::uint8_t> pruned = result.Skeleton;
  SkeletonGraph graph = PruneSegmentsWithoutMajorRidge(
    pruned, major, width, height, settings.MaximumBridgeLength, field, result);
  const std::vector<Segment>& kept = graph.Segments;
  result.KeptSegmentCount = static_cast<int>(kept.size());

  Joiner joiner(kept, graph.SegmentPixels, width, settings, graph.JunctionCount);
  const std::vector<int> link = joiner.JoinAll();
  std::vector<std::vector<int>> contours;
  std::vector<std::uint8_t> closed;
  ContourTracer(kept, graph.SegmentPixels, link).TraceAll(contours, closed);
  std::vector<double> lengths;
  const std::vector<std::uint8_t> keep =
    ContoursToKeep(contours, closed, width, settings, lengths, result);
  for (std::size_t c = 0; c < contours.size(); ++c)
  {
    if (keep[c])
    {
      result.Pixels.insert(result.Pixels.end(), contours[c].begin(), contours[c].end());
      result.Offsets.push_back(static_cast<int>(result.Pixels.size()));
      result.Closed.push_back(closed[c]);
      result.Lengths.push_back(lengths[c]);
    }
  }
  return result;
}

} // namespace tessera
