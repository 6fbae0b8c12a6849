#pragma once
// Ridge contours from minor and major ridges (Goshtasby 2000, sections 2 and 4, steps 3-6).
//
// 1. The minor ridges are thinned to one pixel: the four opposing-pair tests mark bands two
//    pixels wide wherever a ridge runs between the test axes, and in such a band every pixel
//    has three or more neighbours, which would make all of them "branch pixels". Thinning
//    removes, one at a time, pixels that are simple (Yokoi's 8-connectivity number is 1, so
//    removal changes no connectivity and opens no hole) and are not end pixels, peeling from
//    the north, south, east and west borders in turn so the skeleton stays centred.
// 2. Branch pixels are skeleton pixels with three or more neighbours; adjacent branch pixels
//    form one junction. Minor-ridge segments are the maximal runs of the other pixels (at most
//    two neighbours each); a run with no end and no junction is a closed loop.
// 3. Segments without a major-ridge pixel are removed, as branches: a segment with a free end
//    (or a loop) goes, and the graph is rebuilt so that the segments on either side of a
//    branch pixel that lost its branch merge; this repeats until nothing changes. Only then
//    does a segment between two different junctions go without a major pixel, and only if it
//    is longer than MaximumBridgeLength: such a segment that outlived the branches is a saddle
//    path from one ridge to another, while a shorter one lies where ridges cross (the paper
//    removes every segment without a major pixel; major pixels are sparse on noisy crests, see
//    ridge_extraction.h, and removing the pieces between noise branches before the branches
//    would cut the crest). Given the field, a segment between two junctions longer than
//    MaximumBridgeLength without a major pixel, along which the field falls below a quarter of
//    its ends', is a saddle path from the start and goes with the branches (once the branches
//    beyond its junctions went, it merged into the ridges and joined them). The whole step
//    repeats until nothing changes.
// 4. At each junction the remaining segment ends are joined in pairs, best pair first:
//    Longest joins the two ends whose contours (so far) give the longest contour;
//    ClosestTangent joins the two ends whose tangents at the junction are most nearly opposite
//    (the smoothest continuation). An end left over stops at the junction.
// 5. Joined segments are traced into contours, open (two ends) or closed; contours shorter
//    than the minimum length are dropped, and so are open contours (up to MaximumSideStrandLength)
//    whose every pixel lies within SideStrandDistance of the longer contours kept (of equal
//    lengths, the earlier traced counts as longer): side strands of one ridge.
//    A noisy ridge band has pixel-sized holes, which thinning keeps (it never opens or closes
//    one), so the skeleton runs in two strands around each hole; both hold major pixels and
//    stay, the joiner takes one strand through the junctions at either end of the holes, and
//    the spare ends there join into a contour of the other strands, beside the first.
//
//      J1 ====== J2 ====== J3      two strands around holes between junctions J1, J2, J3:
//         \____/  \____/           the long contour takes one (===), the other strands (___)
//                                  join through J2 into a side strand
//
//        spur C                    Longest / ClosestTangent on a straight line A-B
//          \                       with a spur C: A and B are joined through the junction
//   A ------ J ------ B            pixel J, C becomes a contour of its own (usually dropped
//                                  by the minimum length).
//
// Lengths are in pixels: 1 between 4-neighbours, sqrt(2) between diagonal neighbours.

#include <cstdint>
#include <vector>

namespace tessera
{

enum class JoinRule
{
  Longest,       ///< join the pair that makes the longest contour (the paper's procedure)
  ClosestTangent ///< join the pair whose tangents at the branch pixel are closest
};

struct RidgeContourSettings
{
  JoinRule Join = JoinRule::Longest;
  /// Contours shorter than this (pixels) are dropped.
  double MinimumLength = 10.0;
  /// Closed contours shorter than this (pixels) are dropped too (RidgeGrouping: a circle of one
  /// basis width, the smallest loop of the data the field resolves).
  double MinimumLoopLength = 0.0;
  /// How far (pixels along the segment) the tangent of a segment end is measured.
  int TangentPixels = 6;
  /// Longest segment between two junctions kept without a major-ridge pixel (pixels).
  double MaximumBridgeLength = 10.0;
  /// An open contour no longer than MaximumSideStrandLength whose every pixel lies within this
  /// distance (pixels) of the longer contours kept is dropped as a side strand; 0 = none is.
  double SideStrandDistance = 0.0;
  double MaximumSideStrandLength = 0.0;
};

/// Contours as flat arrays: contour c is Pixels[Offsets[c] .. Offsets[c + 1]), pixel indices
/// j * width + i in tracing order. A closed contour does not repeat its first pixel.
struct RidgeContours
{
  std::vector<int> Pixels;
  std::vector<int> Offsets{ 0 };
  std::vector<std::uint8_t> Closed;
  std::vector<double> Lengths; ///< pixels, including the closing step of a closed contour

  int Count() const { return static_cast<int>(this->Closed.size()); }

  // Diagnostics of the intermediate steps, for tests and reports.
  std::vector<std::uint8_t> Skeleton; ///< thinned minor ridges
  int BranchPixelCount = 0;
  int SegmentCount = 0;      ///< minor-ridge segments before removal
  int KeptSegmentCount = 0;  ///< segments holding a major-ridge pixel
  int ShortContourCount = 0; ///< contours dropped as shorter than MinimumLength
  int ShortLoopCount = 0;    ///< closed ones not so dropped, but shorter than MinimumLoopLength
  int SideStrandCount = 0;   ///< open ones dropped beside a longer one (SideStrandDistance)
};

/// Thins a binary mask in place as in step 1 above. O(mask pixels x passes).
void ThinToSkeleton(std::vector<std::uint8_t>& mask, int width, int height);

/// Yokoi's 8-connectivity number of (i, j) in a binary mask: the number of 8-connected
/// foreground components its removal would leave touching it (1 = a simple pixel).
int ConnectivityNumber(const std::vector<std::uint8_t>& mask, int width, int height, int i, int j);

/// Length (pixels) of the straight step between pixel indices a and b (j * width + i):
/// 1 between 4-neighbours, sqrt(2) between diagonal neighbours.
double StepLength(int a, int b, int width);

/// Steps 1-5. field (optional): the field the masks were taken from, width x height, which finds
/// the saddle paths of step 3 while the branches still hold their junctions. Throws InputError if
/// the masks or the field do not match width x height or the settings are invalid (a negative or
/// non-finite length or distance, TangentPixels < 1).
RidgeContours TraceRidgeContours(const std::vector<std::uint8_t>& minor,
  const std::vector<std::uint8_t>& major,
  int width,
  int height,
  const RidgeContourSettings& settings,
  const std::vector<double>* field = nullptr);

} // namespace tessera
