#pragma once
// Goshtasby's grouping and parameterisation of irregularly spaced points (ACM TOG 19(3), 2000):
// the entry point that runs the paper's steps in order and returns everything the
// vtkRidgeGrouping filter outputs.
//
//  1. field surface g = sum of radial bases at the points        (radial_field, by FFT)
//  2. g digitised on an image over the points' bounding box       (pixel_grid; size automatic
//     or given)
//  3-4. minor and major ridges                                    (ridge_extraction)
//  5-6. segments, branch pixels, removal, joining, contours       (ridge_contours)
//  7. partition and nodes                                         (point_partition)
//  8. a rational Gaussian curve per subset                        (rational_gaussian_curve)
//
// Image geometry. The image has ImageSize pixels along the longer side of the bounding box,
// including a margin of ceil(Width) + 2 pixels on every side (so that ridges at the edge of
// the data have neighbours to be tested against); the shorter side gets as many pixels as it
// needs at the same spacing. With ImageSize = 0 the size is chosen as the paper says: the
// smallest of 64, 96, 128, 192, 256, 384, 512, 768, 1024 at which most (more than half) of the
// points fall in a pixel of their own, copies of a point counting as one point (repeated
// measurements cannot be told apart by any image); 1024 (with a warning) when none does, or, for a
// basis so wide (above some 500 pixels) that its margins need more, the smallest size that holds
// them.
//
// Choices the paper leaves open (each explained where it is made):
//  - the field is spread onto the pixel grid bilinearly and convolved by FFT, error bound
//    FieldErrorBound (radial_field.h);
//  - pixels below a millionth of the field's peak are never ridges (Gaussian far field is
//    FFT rounding noise);
//  - the gradient direction of the major-ridge test compares the pixels 3 steps away in each
//    of the 8 directions (the paper: 1 step), which doubles the share of crest pixels found
//    major on noisy data without marking pixels away from the crests;
//  - minor ridges are thinned to one pixel before branch pixels are counted; segments without
//    a major pixel are removed as dangling branches first, and then, between two junctions that
//    remain, when longer than 2 basis widths; an open contour up to 4 widths long within 3.5
//    pixels (and a width) of longer ones all along is dropped as a side strand of their ridge
//    (ridge_contours.h);
//  - points past the end of an open contour get extended nodes (point_partition.h).
//
// Limits. ImageSize may not exceed MaxImageSize = 2048: the padded FFT then holds two complex
// 4096 x 4096 arrays (512 MiB). A larger request is refused with an InputError before anything
// is allocated; so is a basis width whose margins leave no room inside that image (above 1020
// pixels), and a point beyond +-1e306 (the grid and the curves would overflow).

#include "geometry.h"
#include "pixel_grid.h"
#include "radial_field.h"
#include "ridge_contours.h"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace tessera
{

struct RidgeGroupingSettings
{
  RadialBasis Basis = RadialBasis::InverseMultiquadric;
  /// r of the inverse multiquadric or the standard deviation of the Gaussian, in pixels.
  double Width = 5.0;
  /// Pixels along the longer side of the image (margins included); 0 = automatic.
  int ImageSize = 0;
  /// Smoothness of the RaG curves, in node units (the paper uses 0.01 to 0.08), at most
  /// RidgeGrouping::MaxCurveSigma. Smoothing pulls a curve in: a closed one's radius shrinks by
  /// exp(-2 pi^2 sigma^2) (3% at 0.04, 18% at 0.1), and an open one stops short of its points' ends
  /// by some sigma times its length.
  double CurveSigma = 0.04;
  JoinRule Join = JoinRule::Longest;
  /// Ridge contours shorter than this (pixels) are dropped before partitioning, and so are closed
  /// ones shorter than 2 pi Width pixels (a loop the field cannot resolve) and open ones up to
  /// 4 Width pixels long within 3.5 pixels (and Width) of longer contours all along (a side
  /// strand of their ridge, ridge_contours.h).
  double MinimumContourLength = 10.0;
  /// Samples of each fitted curve per pixel of its ridge contour (at least 16 per curve).
  double CurveSamplesPerPixel = 2.0;
};

/// Polylines as flat arrays: line k is Points[Offsets[k] .. Offsets[k + 1]).
struct Polylines
{
  std::vector<Point2> Points;
  std::vector<int> Offsets{ 0 };
  int Count() const { return static_cast<int>(this->Offsets.size()) - 1; }
};

struct RidgeGroupingResult
{
  // Output 0, per input point.
  std::vector<int> GroupId; ///< ridge contour of the point, -1 = unassigned
  std::vector<double> Node; ///< in [0, 1]; 0 when unassigned
  /// Distance (input units) from the point to the contour pixel it is grouped by; NaN where there
  /// is none (unassigned, or every point identical: one group without a contour). A point joins the
  /// nearest contour however far it is (unless a chain of points continues another contour past its
  /// end to it, see point_partition.h): those beyond FarContourWidths basis widths are also named
  /// in a warning; for a point past an open contour's end that continues it (PointPartition's
  /// Continues) the distance is still to the end pixel, but only its distance off the end
  /// tangent's line is held against that limit.
  std::vector<double> ContourDistance;

  // Output 1: ridge contours, pixel centres in input coordinates; ContourId = line index =
  // the GroupId of its points. A closed contour does not repeat its first point.
  Polylines Contours;
  std::vector<std::uint8_t> ContourClosed;
  std::vector<double> ContourLength; ///< in input units

  // Output 2: fitted RaG curves (one per contour with at least two points). A closed curve
  // does not repeat its first point.
  Polylines Curves;
  std::vector<int> CurveGroupId;
  std::vector<std::uint8_t> CurveClosed;

  // Output 3: the field image (empty grid when there was no image to make).
  PixelGrid Grid;
  std::vector<double> Field;
  std::vector<std::uint8_t> MinorRidge;
  std::vector<std::uint8_t> MajorRidge;

  int ImageSize = 0; ///< pixels along the longer side, as used
  bool ImageSizeAutomatic = false;
  double PixelSize = 0.0;       ///< input units per pixel, as used
  double FieldErrorBound = 0.0; ///< bound of |FFT field - direct sum| at any pixel
  /// (point, earlier point) for each point at the x and y of an earlier one (ascending by point):
  /// grouped as any other, the place weighing as often in the field; named in a warning.
  std::vector<std::pair<std::int32_t, std::int32_t>> Duplicates;
  std::vector<std::string> Warnings;
};

class RidgeGrouping
{
public:
  static constexpr int MaxImageSize = 2048;
  static constexpr int MaxAutomaticImageSize = 1024;
  /// Above this CurveSigma a curve is mostly its points' mean: a closed one keeps under 30% of its
  /// radius (exp(-2 pi^2 0.25^2) = 0.29), and at 0.3 it collapsed to a point. An InputError.
  static constexpr double MaxCurveSigma = 0.25;
  /// Points further than this many basis widths from their contour are named in a warning: a
  /// point that far adds almost nothing to the ridge it joins (a Gaussian basis is e^-50 of its
  /// peak there, the inverse multiquadric a tenth), so it joined only for want of a nearer contour,
  /// and it pulls that group's curve. (At 3 widths, 40% of the Fiji epicentres were named.)
  static constexpr double FarContourWidths = 10.0;

  /// Throws InputError for a bad setting, naming it (including an image size over the limit,
  /// with the memory it would need).
  explicit RidgeGrouping(const RidgeGroupingSettings& settings = RidgeGroupingSettings());

  /// Throws InputError naming the first point with a NaN or infinite coordinate. Fewer than two
  /// points give a warning, every point unassigned (GroupId -1) and no contour or curve;
  /// identical points give one group and no curve. progress, if given, is called with the
  /// fraction done after each stage (the image chosen, the field, the contours, the groups and
  /// curves); when it returns false before the last, Run stops and throws Cancelled (a field of
  /// 2048 pixels takes seconds, which a viewer's progress bar spent at one place).
  RidgeGroupingResult Run(const std::vector<Point2>& points,
    const std::function<bool(double)>& progress = nullptr) const;

  /// The field image's grid that Run gives for these points (the image size chosen as Run
  /// chooses it), without computing the field: an empty grid for fewer than two distinct points.
  /// Throws as Run does for a bad point or an image size over the limit.
  PixelGrid ImageGridOf(const std::vector<Point2>& points) const;
  /// Margin in pixels on every side of the bounding box.
  int MarginPixels() const;
  /// The image over the bounding box of points (not all identical) with imageSize pixels
  /// along its longer side.
  PixelGrid MakeGrid(const std::vector<Point2>& points, int imageSize) const;
  /// The paper's automatic choice (see the header comment), counting copies of a point once;
  /// `capped` tells whether no candidate reached a majority of distinct points in pixels of
  /// their own.
  int AutomaticImageSize(const std::vector<Point2>& points, bool& capped) const;
  /// The points with copies (equal coordinates) removed, in lexicographic order.
  static std::vector<Point2> DistinctPoints(const std::vector<Point2>& points);
  /// Fraction of points alone in their (nearest) pixel of grid.
  static double FractionInOwnPixel(const std::vector<Point2>& points, const PixelGrid& grid);

private:
  void CheckImageSize(int imageSize) const;
  /// The image size for points (not all identical): the set one, or the automatic choice
  /// (capped: see AutomaticImageSize); checked against the limits.
  int ChosenImageSize(const std::vector<Point2>& points, bool& capped) const;
  /// Run's image over points (not all identical; extent the larger side of their bounding box):
  /// its size chosen and its grid, both recorded in result with the warnings of a capped
  /// automatic size, a basis below a pixel and points that stretch the image.
  PixelGrid ChooseImage(const std::vector<Point2>& points,
    double extent,
    RidgeGroupingResult& result) const;

  RidgeGroupingSettings Settings;
};

} // namespace tessera
