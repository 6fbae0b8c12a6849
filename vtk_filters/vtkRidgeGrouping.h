/**
 * @class   vtkRidgeGrouping
 * @brief   group noisy scattered points into curves along the ridges of a radial field
 *
 * vtkRidgeGrouping follows Goshtasby (2000): a field surface g(x, y) = sum of radial basis
 * functions centred at the points (inverse multiquadric or Gaussian, width in pixels) is digitised
 * on an image over the points' bounding box (by FFT convolution, with a stated error bound); its
 * minor and major ridges are traced into ridge contours, joined at branch pixels by the longest-
 * contour or the closest-tangent rule; every point goes to the contour with the nearest pixel
 * and gets a node (arc length from the contour's start over its length), however far it lies
 * from it (an outlier joins the nearest group and pulls its curve); a rational Gaussian curve
 * with unit weights is fitted to each group of two or more points (periodic on closed contours;
 * groups of one point are named in a warning). Only x and y are used: points off the plane z = 0
 * are grouped by their x and y, and the contours, curves and image lie at z = 0 (a warning gives
 * the points' z range).
 *
 * The grouping is not invariant under reflection or rotation: the ridges' thinning peels borders
 * in a fixed order, so a mirrored or rotated data set can give other groups where ridges meet or
 * nearly touch (the field and its ridge pixels are mirrored or rotated exactly; a quarter turn of
 * the Fiji epicentres moved a few percent of the points to other groups). A time-varying input is
 * grouped at each time asked, but the field image's extent is announced from the points as
 * RequestInformation finds them, which a change of time alone does not rerun: a time whose grid has
 * another size gives its image on the announced pixels from the lower left corner, cropped or
 * padded (Field NaN, ridges 0), with a warning; modifying the filter announces the grid of the time
 * then.
 *
 * The input is a vtkPointSet, or a composite data set of them whose points are joined in block
 * order into one set (a point layer from vtkGDALVectorReader, a block per feature with its
 * attributes as its vertex's cell data, carried as the point's): ids then count the joined
 * points, and attribute roles such as global ids are not kept. Any other type is an error naming
 * it, with the outputs emptied.
 *
 * Outputs (array names are API):
 * - 0 (vtkPolyData): the input points (one vertex each, point data passed) with point data
 *   `GroupId` (int; the contour of the point, -1 = unassigned), `Node` (double in [0, 1]: the
 *   point's place along its contour, by the contour pixel it is projected on, so points on one
 *   pixel share a Node and have no order among themselves; 0 for an unassigned point, so select
 *   GroupId >= 0 before ordering by Node) and
 *   `ContourDistance` (double; from the point to the contour pixel it is grouped by, in the
 *   points' units, NaN when unassigned or when there is no contour: points beyond 10 basis
 *   widths are named in a warning; for points past an open contour's end that continue it,
 *   each within two widths of the one before, the distance is to the end pixel, and only their
 *   distance off the line of the end's tangent counts for the warning; points more than two
 *   widths beyond their contour pixel along the contour, past an end after a gap or where the
 *   ridge turns away from them, share that pixel's Node with no order, and a warning names them);
 *   an input array of one of those names is passed as NAME_input, with a warning.
 *   Field data `ImageSize` (pixels along the longer side, as used), `PixelSize`,
 *   `FieldErrorBound` (bound of |FFT field - direct sum| at any pixel), `DuplicatePointIds` and
 *   `DuplicateOfPointIds` (vtkIdType: each point at the x and y of an earlier one, and the first
 * point there; they are grouped as any other, the place weighing as often in the field, and named
 * in a warning).
 * - 1 (vtkPolyData): the ridge contours as polylines through pixel centres (a closed contour
 *   repeats its first point), cell data `ContourId` (int, = GroupId of its points, if any),
 *   `Closed` (unsigned char) and `Length` (double: the length of the pixel path, in input units,
 *   steps of 1 and sqrt(2) pixels, which exceeds a smooth curve's where it runs slanted: by 8% on
 *   a circle, 10% on an ellipse, 1% on an axis-aligned square; an open contour stops some basis
 *   widths short of its points' ends, and came out 2-6% shorter than a line's or a sine's).
 * - 2 (vtkPolyData): the fitted curves, finely sampled polylines, cell data `GroupId` and
 *   `Closed`.
 * - 3 (vtkImageData): the field image, point data `Field` (double), `MinorRidge` and
 *   `MajorRidge` (unsigned char, 1 on ridge pixels). GetOutput(3) gives nothing (it casts to
 *   poly data): use GetOutputDataObject(3).
 *
 * Fewer than 2 points give a warning, output 0 holding them unassigned (GroupId -1) and the
 * other outputs empty; a few points (2 or 3, or a few distinct places) make no ridge contour of
 * MinimumContourLength: a warning (saying where the ridges were lost: contours too short, too
 * short a loop, no crest, no ridge), and every point unassigned; identical points give one group
 * (GroupId 0, Node 0, ContourDistance NaN) with no contour and no curve, and a warning. ImageSize 0
 * (default) chooses the size as the paper says (most points in pixels of their own, copies of a
 * point counting once); sizes above 2048 are refused before anything is allocated (the FFT would
 * need more than 512 MiB). NaN or infinite coordinates are an error naming the point. Open
 * contours whose ends lie within 4 basis widths of each other, one looking towards the other (a
 * curve broken where its points lie further apart than the basis reaches; a group's own two ends
 * whichever way they look), are named in a warning with the places, and so is a Width below one
 * pixel. A contour that passes within 4 basis widths of itself where it is much further along
 * itself (running along one curve and back along another beside it, grouping both) is named in a
 * warning with the places; so is a group with many points (a tenth of it, at least 10) more than 2
 * basis widths to one side of its contour (another curve beside it whose ridge stopped or crossed
 * over to this one, or a spread of points the ridge does not follow). Contours that run more than
 * 3 basis widths
 * from every point (the field's ridge across empty space, which can join points of curves far
 * apart into one group) are named with the stretch, and so are contours that no point is grouped
 * by (they are in output 1 with no group and no curve). The image spans every point, so a few
 * stray points far from the rest leave the rest few pixels: where the box of the points without
 * the most extreme 1% on each side spans under 6 basis widths and under a quarter of the image,
 * the points further outside it than its size (and an eighth of the image) are named with their
 * places (one point 200 radii from a circle of 500 left the circle 2 basis widths across, and
 * nothing grouped).
 */

#ifndef vtkRidgeGrouping_h
#define vtkRidgeGrouping_h

#include "tesseraFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class TESSERAFILTERS_EXPORT vtkRidgeGrouping : public vtkPolyDataAlgorithm
{
public:
  static vtkRidgeGrouping* New();
  vtkTypeMacro(vtkRidgeGrouping, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum BasisTypes
  {
    INVERSE_MULTIQUADRIC = 0,
    GAUSSIAN = 1
  };
  enum JoinRules
  {
    LONGEST = 0,
    CLOSEST_TANGENT = 1
  };

  ///@{
  /**
   * The radial basis: inverse multiquadric [d^2 + r^2]^(-1/2) (default, the paper's first) or
   * Gaussian exp(-d^2 / 2 s^2). The inverse multiquadric's field falls off slowly, so near other
   * points its ridges slope along themselves, and where that slope beats the drop across them
   * few pixels pass the paper's major-ridge test: at the automatic image size, two noisy lines
   * crossing at a right angle gave no contour (every point unassigned, with a warning), two
   * noisy concentric circles 50 units apart one group, and a noisy spiral a contour of a fifth
   * of its length. The Gaussian, whose field falls off fast, or a larger ImageSize (256 there)
   * grouped all three correctly; try them when groups are missing or merged, as trials on the data
   * at hand (they depend on it: another noisy spiral gave one group at the automatic size and 4
   * at 256 pixels). Another value is an error at the update.
   */
  vtkSetMacro(Basis, int);
  // The range VTK's clamping setter announced (kept: a value outside is an error at the update).
  virtual int GetBasisMinValue() { return INVERSE_MULTIQUADRIC; }
  virtual int GetBasisMaxValue() { return GAUSSIAN; }
  vtkGetMacro(Basis, int);
  void SetBasisToInverseMultiquadric() { this->SetBasis(INVERSE_MULTIQUADRIC); }
  void SetBasisToGaussian() { this->SetBasis(GAUSSIAN); }
  ///@}

  ///@{
  /**
   * Width of the basis (r or s) in pixels (default 5). A width that is not positive, below 1e-150
   * (its square underflows), or whose margins leave no room inside the largest image (above
   * 1020), is an error at the update.
   */
  vtkSetMacro(Width, double);
  vtkGetMacro(Width, double);
  ///@}

  ///@{
  /**
   * Pixels along the longer side of the image, margins included; 0 (default) = automatic. A
   * negative size, one above 2048, or one below 2 (ceil(Width) + 2) + 3 (no room inside the
   * margins) is an error at the update.
   */
  vtkSetMacro(ImageSize, int);
  vtkGetMacro(ImageSize, int);
  ///@}

  ///@{
  /**
   * Smoothness of the fitted rational Gaussian curves, in node units (default 0.04; the paper
   * uses 0.01 to 0.08). A group's nodes run from 0 to 1, so the smoothing in data units grows
   * with the curve's length: 0.04 rounds off long or closed curves, which 0.01-0.02 follows.
   * Smoothing pulls a curve in: a closed one's radius shrinks by exp(-2 pi^2 sigma^2) (3% at 0.04,
   * 18% at 0.1), and an open one stops short of its points' ends by about sigma times its length.
   * Not positive, below 1e-150 (its square underflows) or above 0.25 (the curve shrinks towards
   * its points' mean): an error at the update.
   */
  vtkSetMacro(CurveSigma, double);
  vtkGetMacro(CurveSigma, double);
  ///@}

  ///@{
  /**
   * How ridge segments are joined at branch pixels: longest contour (default, the paper's) or
   * closest tangent. Where two curves cross, the longest contour may turn onto the other curve
   * (two L-shaped groups); closest tangent tends to keep each curve straight through the crossing,
   * but where the two ridges merge before it (a shallow angle, or the inverse multiquadric's wide
   * ridges at a right angle) the points of both curves can still fall into one or mixed groups,
   * or into none (see Basis). Another value is an error at the update.
   */
  vtkSetMacro(JoinRule, int);
  // The range VTK's clamping setter announced (kept: a value outside is an error at the update).
  virtual int GetJoinRuleMinValue() { return LONGEST; }
  virtual int GetJoinRuleMaxValue() { return CLOSEST_TANGENT; }
  vtkGetMacro(JoinRule, int);
  void SetJoinRuleToLongest() { this->SetJoinRule(LONGEST); }
  void SetJoinRuleToClosestTangent() { this->SetJoinRule(CLOSEST_TANGENT); }
  ///@}

  ///@{
  /**
   * Ridge contours shorter than this many pixels are dropped before partitioning (default 10),
   * and so are closed ones shorter than a circle of one basis width (2 pi Width pixels: a loop
   * the field cannot resolve, made by its shape where a curve ends or bends) and open ones up to
   * 4 Width pixels long within 3.5 pixels (and Width) of longer contours all along (a second
   * strand of their ridge around small holes in its band, which took a few points of a noisy
   * circle into a group of their own), without a warning. Negative: an error at the update.
   */
  vtkSetMacro(MinimumContourLength, double);
  vtkGetMacro(MinimumContourLength, double);
  ///@}

protected:
  vtkRidgeGrouping();
  ~vtkRidgeGrouping() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Basis = INVERSE_MULTIQUADRIC;
  double Width = 5.0;
  int ImageSize = 0;
  double CurveSigma = 0.04;
  int JoinRule = LONGEST;
  double MinimumContourLength = 10.0;

private:
  vtkRidgeGrouping(const vtkRidgeGrouping&) = delete;
  void operator=(const vtkRidgeGrouping&) = delete;
};

#endif
