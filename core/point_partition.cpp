#include "point_partition.h"

#include "distance_transform.h"
#include "errors.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <string>
#include <utility>

namespace tessera
{

namespace
{

void CheckPoint(const Point2& p, std::size_t index, int width, int height)
{
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
  {
    throw InputError("point " + std::to_string(index) + " has a NaN or infinite coordinate");
  }
  if (p.x < -0.5 || p.y < -0.5 || p.x > width - 0.5 || p.y > height - 0.5)
  {
    throw InputError("point " + std::to_string(index) + " lies outside the " +
      std::to_string(width) + " x " + std::to_string(height) + " image");
  }
}

// The centre of the image's pixel of index `pixel` (pixel units).
Point2 PixelCentre(int pixel, int width)
{
  return { double(pixel % width), double(pixel / width) };
}

double SquaredDistanceToPixel(const Point2& p, int pixel, int width)
{
  const double dx = p.x - pixel % width;
  const double dy = p.y - pixel / width;
  return dx * dx + dy * dy;
}

// The nearest contour pixel to p among the nearest features of p's pixel and its neighbours.
int NearestContourPixel(const Point2& p, const std::vector<int>& nearest, int width, int height)
{
  const int ci = std::clamp(static_cast<int>(std::lround(p.x)), 0, width - 1);
  const int cj = std::clamp(static_cast<int>(std::lround(p.y)), 0, height - 1);
  int best = -1;
  double bestDistance = 0.0;
  for (int dj = -1; dj <= 1; ++dj)
  {
    for (int di = -1; di <= 1; ++di)
    {
      const int i = ci + di;
      const int j = cj + dj;
      if (i < 0 || j < 0 || i >= width || j >= height)
      {
        continue;
      }
      const int candidate = nearest[static_cast<std::size_t>(j) * width + i];
      const double distance = SquaredDistanceToPixel(p, candidate, width);
      if (best < 0 || distance < bestDistance)
      {
        best = candidate;
        bestDistance = distance;
      }
    }
  }
  return best;
}

// How far p lies beyond pixel `at` in the direction from pixel `from` to pixel `to` (pixel
// indices of an image `width` wide); 0 where from and to are one pixel.
double DistanceAlong(const Point2& p, int at, int from, int to, int width)
{
  const double tx = to % width - from % width;
  const double ty = to / width - from / width;
  const double norm = std::hypot(tx, ty);
  return norm > 0.0 ? ((p.x - at % width) * tx + (p.y - at / width) * ty) / norm : 0.0;
}

// How many pixels before an end of an open contour (of two pixels or more) its tangent there is
// taken over: up to 5, as one pixel step only gives the 8 chain-code directions.
int EndTangentReach(const RidgeContours& contours, int contour)
{
  return std::min(5, contours.Offsets[contour + 1] - 1 - contours.Offsets[contour]);
}

// The pixel from which the tangent at the end pixel `position` of an open contour is taken.
int EndTangentPixel(const RidgeContours& contours, int contour, int position)
{
  const int first = contours.Offsets[contour];
  const int last = contours.Offsets[contour + 1] - 1;
  const int reach = EndTangentReach(contours, contour);
  return contours.Pixels[position == first ? first + reach : last - reach];
}

// How far p lies past the end pixel `position` of an open contour, along the contour's direction
// at that end (0 if it is not an end pixel, the contour is closed, or p is not past it).
double DistanceBeyondEnd(const Point2& p,
  const RidgeContours& contours,
  int contour,
  int position,
  int width)
{
  const int first = contours.Offsets[contour];
  const int last = contours.Offsets[contour + 1] - 1;
  if (contours.Closed[contour] || last == first || (position != first && position != last))
  {
    return 0.0;
  }
  const int end = contours.Pixels[position];
  return std::max(
    0.0, DistanceAlong(p, end, EndTangentPixel(contours, contour, position), end, width));
}

// The centre of the pixel at `position` of contours.Pixels.
Point2 PositionCentre(const RidgeContours& contours, int position, int width)
{
  return PixelCentre(contours.Pixels[std::size_t(position)], width);
}

// Whether the pixel at `position` of an open contour lies behind its end pixel at `end` along the
// end tangent (strictly).
bool PixelBehindEnd(const RidgeContours& contours, int contour, int position, int end, int width)
{
  const int endPixel = contours.Pixels[end];
  return DistanceAlong(PositionCentre(contours, position, width),
           endPixel,
           EndTangentPixel(contours, contour, end),
           endPixel,
           width) < 0.0;
}

// The projection of p, whose nearest pixel is at `position` of `contour`, and its distance beyond
// that pixel's end (DistanceBeyondEnd; 0 when not past an end). A point nearest to one of the
// pixels an end's tangent is taken over, but lying beyond the end pixel along that tangent, is
// past the end too: it is projected on the end pixel. Ridge contours often hook at an end (the
// crest bends where the points stop), and the points continuing the curve were then nearer to a
// pixel just before the end than to the end pixel: they all took that pixel's node, in no order.
//
//   = = = = = = 1                 contour hooking at its end E; the points x continue it
//                E    x   x   x   beyond E along the end tangent, but are nearer to pixel 1
//
// Only where the nearest pixel lies behind the end pixel along that tangent: a contour that turns
// back within those pixels (U-shaped at its end) has pixels beyond its end pixel, and a point
// beside them is beside the contour, not past it (moved, it took the largest node, out of order).
//
//   = = = = = = 1                 a U-turn: pixels 1 and 2 lie beyond E along the end tangent
//             E   2   y           (measured from 5 pixels back); y, nearest to 2, keeps 2
//
// Where both ends qualify (a contour of a few pixels), the nearer end pixel is taken.
std::pair<int, double> ProjectionPastEnds(const Point2& p,
  const RidgeContours& contours,
  int contour,
  int position,
  int width)
{
  std::pair<int, double> projection{ position, 0.0 };
  const int first = contours.Offsets[contour];
  const int last = contours.Offsets[contour + 1] - 1;
  if (contours.Closed[contour] || last == first)
  {
    return projection;
  }
  double nearest = std::numeric_limits<double>::infinity();
  for (const int end : { first, last })
  {
    if (std::abs(position - end) > EndTangentReach(contours, contour) ||
      (position != end && !PixelBehindEnd(contours, contour, position, end, width)))
    {
      continue;
    }
    const double beyond = DistanceBeyondEnd(p, contours, contour, end, width);
    const double distance = SquaredDistanceToPixel(p, contours.Pixels[end], width);
    if (beyond > 0.0 && distance < nearest)
    {
      projection = { end, beyond };
      nearest = distance;
    }
  }
  return projection;
}

// The points past one contour end, in order of their distance beyond it (along the end tangent),
// continue the curve while each lies at most maximumGap further than the one before (the first:
// than the end pixel). From the first gap on they are taken as outliers: each gets the distance of
// the last continuation (0: the end pixel's node, the paper's), so that one far point cannot
// stretch the node range and squeeze the nodes of every other point of the contour.
//
//   contour   continuations    gap > maximumGap     outlier
//   ======E   . . .. . .  ----------------------->    x      (x gets the node of the last dot)
//
// Points reached by a chain past an end (FollowChainsPastEnds) have their distances already, with
// steps of at most maximumGap from the end: they always count as continuations here (and keep the
// Continues that the chain gave them), so the gap rule only applies to the other points.
void KeepContinuationsOnly(std::vector<double>& beyond,
  const std::vector<int>& projection,
  const std::vector<std::uint8_t>& chained,
  double maximumGap,
  std::vector<std::uint8_t>& continues)
{
  std::vector<std::size_t> past; // the points past an end, by end pixel, then distance
  for (std::size_t k = 0; k < beyond.size(); ++k)
  {
    if (beyond[k] > 0.0)
    {
      past.push_back(k);
    }
  }
  std::sort(past.begin(),
    past.end(),
    [&](std::size_t a, std::size_t b) {
      return projection[a] != projection[b] ? projection[a] < projection[b] : beyond[a] < beyond[b];
    });
  double last = 0.0; // distance of the last continuation past the current end
  bool outliers = false;
  for (std::size_t m = 0; m < past.size(); ++m)
  {
    const std::size_t k = past[m];
    if (m == 0 || projection[k] != projection[past[m - 1]])
    {
      last = 0.0;
      outliers = false;
    }
    if (chained[k])
    {
      last = std::max(last, beyond[k]);
      outliers = false;
      continue;
    }
    outliers = outliers || beyond[k] - last > maximumGap;
    if (outliers)
    {
      beyond[k] = last;
    }
    else
    {
      last = beyond[k];
      continues[k] = 1;
    }
  }
}

// The far points (more than maximumGap from their nearest contour pixel) in a k-d tree that gives
// up the points it reports: each point is reported once, and a search only descends into boxes
// holding points not yet taken, within reach and on the right side of a line, so that growing the
// chains costs about O(F sqrt F) for F far points however densely they lie (a grid of cells of
// side maximumGap met every untaken point of the 3 x 3 cells at every step: 80 s for 200,000 far
// points in a 60 x 60 pixel patch).
class FarPointTree
{
public:
  FarPointTree(const std::vector<Point2>& points, std::vector<std::size_t> members)
    : Points(points)
    , Members(std::move(members))
    , Alive(this->Members.size(), 1)
  {
    if (!this->Members.empty())
    {
      this->Build(0, this->Members.size());
    }
  }

  /// Takes out of the tree, and appends to taken, every point k within radius of centre that
  /// accept(k) accepts, searching only boxes with a place p where (p - origin) . direction >= 0.
  template<typename Accept>
  void Take(const Point2& centre,
    double radius,
    const Point2& origin,
    const Point2& direction,
    Accept&& accept,
    std::vector<std::size_t>& taken)
  {
    if (!this->Nodes.empty())
    {
      // A little wide: the points' own test (accept) decides at the boundary.
      const double reach = radius * radius * (1.0 + 1e-9);
      this->Take(0, centre, reach, origin, direction, accept, taken);
    }
  }

private:
  struct Node
  {
    std::size_t Lo = 0, Hi = 0, Live = 0;
    double XMin = 0.0, XMax = 0.0, YMin = 0.0, YMax = 0.0;
    int Left = -1, Right = -1; // leaves: -1
  };

  int Build(std::size_t lo, std::size_t hi)
  {
    const int index = static_cast<int>(this->Nodes.size());
    this->Nodes.emplace_back();
    Node node;
    node.Lo = lo;
    node.Hi = hi;
    node.Live = hi - lo;
    node.XMin = node.YMin = std::numeric_limits<double>::infinity();
    node.XMax = node.YMax = -std::numeric_limits<double>::infinity();
    for (std::size_t m = lo; m < hi; ++m)
    {
      const Point2& p = this->Points[this->Members[m]];
      node.XMin = std::min(node.XMin, p.x);
      node.XMax = std::max(node.XMax, p.x);
      node.YMin = std::min(node.YMin, p.y);
      node.YMax = std::max(node.YMax, p.y);
    }
    if (hi - lo > 8)
    {
      const std::size_t mid = lo + (hi - lo) / 2;
      const bool alongX = node.XMax - node.XMin >= node.YMax - node.YMin;
      std::nth_element(this->Members.begin() + std::ptrdiff_t(lo),
        this->Members.begin() + std::ptrdiff_t(mid),
        this->Members.begin() + std::ptrdiff_t(hi),
        [&](std::size_t a, std::size_t b) {
          return alongX ? this->Points[a].x < this->Points[b].x
                        : this->Points[a].y < this->Points[b].y;
        });
      node.Left = this->Build(lo, mid);
      node.Right = this->Build(mid, hi);
    }
    this->Nodes[std::size_t(index)] = node;
    return index;
  }

  template<typename Accept>
  std::size_t Take(int index,
    const Point2& centre,
    double reach,
    const Point2& origin,
    const Point2& direction,
    Accept& accept,
    std::vector<std::size_t>& taken)
  {
    Node& node = this->Nodes[std::size_t(index)];
    if (node.Live == 0)
    {
      return 0;
    }
    const double dx = std::max({ node.XMin - centre.x, 0.0, centre.x - node.XMax });
    const double dy = std::max({ node.YMin - centre.y, 0.0, centre.y - node.YMax });
    // The box corner furthest along direction.
    const double most = ((direction.x > 0.0 ? node.XMax : node.XMin) - origin.x) * direction.x +
      ((direction.y > 0.0 ? node.YMax : node.YMin) - origin.y) * direction.y;
    if (dx * dx + dy * dy > reach || most < 0.0)
    {
      return 0;
    }
    std::size_t removed = 0;
    if (node.Left < 0)
    {
      for (std::size_t m = node.Lo; m < node.Hi; ++m)
      {
        if (this->Alive[m] && accept(this->Members[m]))
        {
          this->Alive[m] = 0;
          taken.push_back(this->Members[m]);
          ++removed;
        }
      }
    }
    else
    {
      removed = this->Take(node.Left, centre, reach, origin, direction, accept, taken) +
        this->Take(node.Right, centre, reach, origin, direction, accept, taken);
    }
    node.Live -= removed;
    return removed;
  }

  const std::vector<Point2>& Points;
  std::vector<std::size_t> Members; // far point indices, each node's a contiguous range
  std::vector<std::uint8_t> Alive;  // per place in Members: not yet taken
  std::vector<Node> Nodes;          // the root first
};

// Ends: 2c (first pixel) and 2c + 1 (last pixel) of each open contour of two pixels or more.
std::vector<int> OpenContourEnds(const RidgeContours& contours)
{
  std::vector<int> ends;
  for (int c = 0; c < contours.Count(); ++c)
  {
    if (!contours.Closed[c] && contours.Offsets[c + 1] - contours.Offsets[c] >= 2)
    {
      ends.push_back(2 * c);
      ends.push_back(2 * c + 1);
    }
  }
  return ends;
}

// The position in contours.Pixels of end `end` (OpenContourEnds).
int EndPosition(const RidgeContours& contours, int end)
{
  return end % 2 ? contours.Offsets[end / 2 + 1] - 1 : contours.Offsets[end / 2];
}

// Per point, whether it is far: more than maximumGap from its nearest pixel (nearestPositions);
// farPoints: those points, ascending.
std::vector<std::uint8_t> FarFromContours(const std::vector<Point2>& points,
  const RidgeContours& contours,
  const std::vector<int>& nearestPositions,
  int width,
  double maximumGap,
  std::vector<std::size_t>& farPoints)
{
  std::vector<std::uint8_t> far(points.size(), 0);
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const Point2 nearest = PositionCentre(contours, nearestPositions[k], width);
    far[k] = std::hypot(points[k].x - nearest.x, points[k].y - nearest.y) > maximumGap;
    if (far[k])
    {
      farPoints.push_back(k);
    }
  }
  return far;
}

// The chains of FollowChainsPastEnds, grown from all ends at once in order of their length: a
// breadth-first search by distance over the far points, each taken out of a FarPointTree when
// first reached.
class ChainsPastEnds
{
public:
  ChainsPastEnds(const std::vector<Point2>& points,
    const RidgeContours& contours,
    int width,
    double maximumGap,
    const std::vector<std::uint8_t>& far,
    std::vector<std::size_t> farPoints)
    : Points(points)
    , Contours(contours)
    , Width(width)
    , MaximumGap(maximumGap)
    , Far(far)
    , Tree(points, std::move(farPoints))
    , EndOf(points.size(), -1)
    , Parent(points.size(), -1)
  {
  }

  // Queues the chains' starts: the end pixels, and the near points already past an end.
  void Start(const std::vector<int>& ends, const PointPartition& result)
  {
    for (const int end : ends)
    {
      this->Queue.push({ 0.0, -1 - std::ptrdiff_t(end) });
    }
    // (A far point lies more than maximumGap from every contour pixel, ends included: but for
    // near-ties of the nearest pixel the chains start at these near points, not at the end pixels.)
    for (std::size_t k = 0; k < this->Points.size(); ++k)
    {
      const int position = result.Projection[k];
      if (!this->Far[k] && result.Beyond[k] > 0.0)
      {
        const int contour = result.GroupId[k];
        this->EndOf[k] = 2 * contour + (position == this->Contours.Offsets[contour] ? 0 : 1);
        const Point2 e = PositionCentre(this->Contours, position, this->Width);
        this->Queue.push(
          { std::hypot(this->Points[k].x - e.x, this->Points[k].y - e.y), std::ptrdiff_t(k) });
      }
    }
  }

  // Grows the chains until no far point within reach is left.
  void Grow()
  {
    while (!this->Queue.empty())
    {
      const auto [distance, place] = this->Queue.top();
      this->Queue.pop();
      this->StepFrom(distance, place);
    }
  }

  // Gives each far point reached its chain's contour, end pixel and distance beyond the end, and
  // marks it chained.
  void AssignReached(PointPartition& result, std::vector<std::uint8_t>& chained) const
  {
    // In settling order a chain's earlier points come first, so a parent's Beyond is its chain's
    // when its children read it; near points that started a chain keep their own distance.
    for (const std::size_t k : this->Order)
    {
      const int end = this->EndOf[k];
      const int contour = end / 2;
      const int position = EndPosition(this->Contours, end);
      const double own =
        DistanceBeyondEnd(this->Points[k], this->Contours, contour, position, this->Width);
      const double before = this->Parent[k] < 0 ? 0.0 : result.Beyond[std::size_t(this->Parent[k])];
      result.GroupId[k] = contour;
      result.Projection[k] = position;
      result.Beyond[k] = std::max(own, before);
      result.Continues[k] = own >= result.Beyond[k] - this->MaximumGap;
      chained[k] = 1;
    }
  }

private:
  // Settles the chain's place (a point k as k, an end e as -1 - e) at `distance` along its chain,
  // and queues the far points one step from it, beyond its end.
  void StepFrom(double distance, std::ptrdiff_t place)
  {
    const int end = place < 0 ? int(-1 - place) : this->EndOf[std::size_t(place)];
    const int contour = end / 2;
    const int position = EndPosition(this->Contours, end);
    const Point2 endPixel = PositionCentre(this->Contours, position, this->Width);
    const Point2 from = place < 0 ? endPixel : this->Points[std::size_t(place)];
    if (place >= 0 && this->Far[std::size_t(place)])
    {
      this->Order.push_back(std::size_t(place));
    }
    const int inner = EndTangentPixel(this->Contours, contour, position);
    const Point2 tangent{ endPixel.x - inner % this->Width, endPixel.y - inner / this->Width };
    this->Taken.clear();
    this->Tree.Take(
      from,
      this->MaximumGap,
      endPixel,
      tangent,
      [&](std::size_t q)
      {
        return std::hypot(this->Points[q].x - from.x, this->Points[q].y - from.y) <=
          this->MaximumGap &&
          DistanceBeyondEnd(this->Points[q], this->Contours, contour, position, this->Width) > 0.0;
      },
      this->Taken);
    for (const std::size_t q : this->Taken)
    {
      this->EndOf[q] = end;
      this->Parent[q] = place;
      this->Queue.push(
        { distance + std::hypot(this->Points[q].x - from.x, this->Points[q].y - from.y),
          std::ptrdiff_t(q) });
    }
  }

  const std::vector<Point2>& Points;
  const RidgeContours& Contours;
  const int Width;
  const double MaximumGap;
  const std::vector<std::uint8_t>& Far;
  FarPointTree Tree;
  std::vector<int> EndOf;
  std::vector<std::ptrdiff_t> Parent; // -1 - e: the pixel of end e
  std::vector<std::size_t> Order;     // far points, in the order their chains grow from
  // Queue entries: chain length, then place: a point k as k, an end e as -1 - e. Each point is
  // queued once, when first reached: its end is that of the shortest chain reaching it so far
  // (growing in order of chain length, the first is almost always the shortest).
  using Entry = std::pair<double, std::ptrdiff_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> Queue;
  std::vector<std::size_t> Taken; // scratch: the points one step takes
};

// Far points that continue an open contour past its end, taken from their nearest contour (see
// point_partition.h). From each end, chains grow over far points lying beyond the end (along its
// tangent), each step at most maximumGap; they start at a point of the contour already continuing
// it past that end (projected on the end pixel, beyond it: near points are never taken, but they
// start chains), or at the end pixel itself (for near-ties of the nearest pixel). Chains from all
// ends grow at once in order of their length (sum of steps), and a point joins the first that
// reaches it: a breadth-first search by distance, so the end nearest along the chains wins. (Unlike
// Dijkstra's search, which looks at every pair of points within maximumGap, it meets each point
// once: dense far points cost no more than sparse ones.) A reached point gets the end's contour
// and pixel, and as distance beyond the end the largest along its chain from the end to it, so
// that the nodes do not run back where the chain turns; if that is more than maximumGap beyond the
// point's own distance (the chain came back), its order is not known and it does not count as
// continuing (as an outlier after a gap). Returns which points were reached; the others keep their
// nearest contour. nearestPositions: each point's nearest pixel (its projection may be an end
// pixel beyond it, ProjectionPastEnds), by which a point is near or far.
std::vector<std::uint8_t> FollowChainsPastEnds(const std::vector<Point2>& points,
  const RidgeContours& contours,
  const std::vector<int>& nearestPositions,
  int width,
  double maximumGap,
  PointPartition& result)
{
  std::vector<std::uint8_t> chained(points.size(), 0);
  // No limit (or none to speak of): every point near, nothing to follow.
  if (!(maximumGap > 0.0) || !std::isfinite(maximumGap))
  {
    return chained;
  }
  std::vector<std::size_t> farPoints;
  const std::vector<std::uint8_t> far =
    FarFromContours(points, contours, nearestPositions, width, maximumGap, farPoints);
  const std::vector<int> ends = OpenContourEnds(contours);
  if (farPoints.empty() || ends.empty())
  {
    return chained;
  }
  ChainsPastEnds chains(points, contours, width, maximumGap, far, std::move(farPoints));
  chains.Start(ends, result);
  chains.Grow();
  chains.AssignReached(result, chained);
  return chained;
}

/// The pixels up to 3 before and after position along contour c (wrapping round a closed
/// contour, stopping at an open one's ends), between which its tangent there is taken.
std::pair<int, int> TangentPixels(const RidgeContours& contours, int c, int position)
{
  const int first = contours.Offsets[c], count = contours.Offsets[c + 1] - first;
  const int reach = std::min(3, count / 2);
  const auto at = [&](int offset)
  {
    const int k = position - first + offset;
    return contours.Pixels[std::size_t(
      first + (contours.Closed[c] ? ((k % count) + count) % count : std::clamp(k, 0, count - 1)))];
  };
  return { at(-reach), at(reach) };
}

/// Where each contour pixel is: per grid pixel, whether a contour holds it and its position in
/// contours.Pixels; per position, its contour.
struct ContourPixelIndex
{
  std::vector<std::uint8_t> IsContour;
  std::vector<int> PositionOf;
  std::vector<int> ContourOfPosition;
};

ContourPixelIndex IndexContourPixels(const RidgeContours& contours, int width, int height)
{
  // Where contours share a junction pixel the later contour owns it; either is equally near.
  const std::size_t pixelCount = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  ContourPixelIndex index;
  index.IsContour.assign(pixelCount, 0);
  index.PositionOf.assign(pixelCount, -1);
  index.ContourOfPosition.assign(contours.Pixels.size(), -1);
  for (int c = 0; c < contours.Count(); ++c)
  {
    for (int k = contours.Offsets[c]; k < contours.Offsets[c + 1]; ++k)
    {
      index.IsContour[contours.Pixels[k]] = 1;
      index.PositionOf[contours.Pixels[k]] = k;
      index.ContourOfPosition[k] = c;
    }
  }
  return index;
}

/// Gives each point the contour of its nearest contour pixel (GroupId), and its projection on
/// that contour with its distance beyond an end (ProjectionPastEnds: Projection and Beyond).
/// nearest: the contours' nearest-feature transform. Returns each point's nearest pixel's
/// position, by which FollowChainsPastEnds tells near points from far ones.
std::vector<int> ProjectOntoNearestContours(const std::vector<Point2>& pixelPoints,
  const RidgeContours& contours,
  const ContourPixelIndex& index,
  const std::vector<int>& nearest,
  int width,
  int height,
  PointPartition& result)
{
  std::vector<int> nearestPositions(pixelPoints.size());
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    const int pixel = NearestContourPixel(pixelPoints[k], nearest, width, height);
    const int position = index.PositionOf[pixel];
    const int contour = index.ContourOfPosition[position];
    nearestPositions[k] = position;
    result.GroupId[k] = contour;
    std::tie(result.Projection[k], result.Beyond[k]) =
      ProjectionPastEnds(pixelPoints[k], contours, contour, position, width);
  }
  return nearestPositions;
}

/// Each point's arc length along its contour, extended past an end by its distance beyond it,
/// and per contour the range those arc lengths span (from 0 and the contour's length).
struct ExtendedArcs
{
  std::vector<double> Arc, Lowest, Highest;
};

/// The points' extended arc lengths; a point beyond an end is marked Extended.
ExtendedArcs ExtendArcsPastEnds(const RidgeContours& contours, PointPartition& result)
{
  const std::size_t pointCount = result.GroupId.size();
  ExtendedArcs arcs;
  arcs.Arc.assign(pointCount, 0.0);
  arcs.Lowest.assign(contours.Count(), 0.0);
  arcs.Highest.assign(contours.Lengths.begin(), contours.Lengths.end());
  for (std::size_t k = 0; k < pointCount; ++k)
  {
    const int position = result.Projection[k];
    const int contour = result.GroupId[k];
    const double beyond = result.Beyond[k];
    arcs.Arc[k] = result.ArcLength[position];
    if (beyond > 0.0)
    {
      result.Extended[k] = 1;
      arcs.Arc[k] += position == contours.Offsets[contour] ? -beyond : beyond;
      arcs.Lowest[contour] = std::min(arcs.Lowest[contour], arcs.Arc[k]);
      arcs.Highest[contour] = std::max(arcs.Highest[contour], arcs.Arc[k]);
    }
  }
  return arcs;
}

/// Maps each contour's range of extended arc lengths onto nodes 0 to 1 (NodeOrigin and
/// NodePerPixel), and each point's extended arc length onto its Node.
void PlaceNodes(int contourCount, const ExtendedArcs& arcs, PointPartition& result)
{
  result.NodeOrigin.resize(contourCount);
  result.NodePerPixel.resize(contourCount);
  for (int c = 0; c < contourCount; ++c)
  {
    const double span = arcs.Highest[c] - arcs.Lowest[c];
    result.NodePerPixel[c] = span > 0.0 ? 1.0 / span : 0.0;
    result.NodeOrigin[c] = -arcs.Lowest[c] * result.NodePerPixel[c];
  }
  for (std::size_t k = 0; k < arcs.Arc.size(); ++k)
  {
    const int c = result.GroupId[k];
    result.Node[k] =
      std::clamp(result.NodeOrigin[c] + arcs.Arc[k] * result.NodePerPixel[c], 0.0, 1.0);
  }
}

} // namespace

std::vector<double> ContourArcLengths(const RidgeContours& contours, int width)
{
  std::vector<double> arc(contours.Pixels.size(), 0.0);
  for (int c = 0; c < contours.Count(); ++c)
  {
    for (int k = contours.Offsets[c] + 1; k < contours.Offsets[c + 1]; ++k)
    {
      arc[k] = arc[k - 1] + StepLength(contours.Pixels[k - 1], contours.Pixels[k], width);
    }
  }
  return arc;
}

PointPartition PartitionPoints(const std::vector<Point2>& pixelPoints,
  const RidgeContours& contours,
  int width,
  int height,
  double maximumGap)
{
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    CheckPoint(pixelPoints[k], k, width, height);
  }
  PointPartition result;
  result.GroupId.assign(pixelPoints.size(), -1);
  result.Node.assign(pixelPoints.size(), 0.0);
  result.Projection.assign(pixelPoints.size(), -1);
  result.ArcLength = ContourArcLengths(contours, width);
  if (contours.Count() == 0)
  {
    return result;
  }
  const ContourPixelIndex index = IndexContourPixels(contours, width, height);
  const std::vector<int> nearest = NearestFeatureTransform(index.IsContour, width, height);
  result.Extended.assign(pixelPoints.size(), 0);
  result.Continues.assign(pixelPoints.size(), 0);
  result.Beyond.assign(pixelPoints.size(), 0.0);
  const std::vector<int> nearestPositions =
    ProjectOntoNearestContours(pixelPoints, contours, index, nearest, width, height, result);
  const std::vector<std::uint8_t> chained =
    FollowChainsPastEnds(pixelPoints, contours, nearestPositions, width, maximumGap, result);
  KeepContinuationsOnly(result.Beyond, result.Projection, chained, maximumGap, result.Continues);
  PlaceNodes(contours.Count(), ExtendArcsPastEnds(contours, result), result);
  return result;
}

std::vector<std::size_t> PointsWithoutOrder(const std::vector<Point2>& pixelPoints,
  const RidgeContours& contours,
  const PointPartition& partition,
  int width,
  double maximumGap)
{
  std::vector<std::size_t> tied;
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    const int position = partition.Projection[k];
    if (position < 0 || partition.Continues[k])
    {
      continue;
    }
    const auto [before, after] = TangentPixels(contours, partition.GroupId[k], position);
    const int pixel = contours.Pixels[std::size_t(position)];
    if (std::fabs(DistanceAlong(pixelPoints[k], pixel, before, after, width)) > maximumGap)
    {
      tied.push_back(k);
    }
  }
  return tied;
}

} // namespace tessera
