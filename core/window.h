#pragma once
// A convex window given by strict linear constraints a*x + b*y + c < 0 (Green and Sibson,
// section 1.2). Redundant constraints are identified and ignored; an empty or unbounded window is
// an InputError (UnboundedWindowError for the latter).

#include "errors.h"
#include "geometry.h"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera
{

/// The open half-plane a*x + b*y + c < 0.
struct HalfPlane
{
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
};

/// The InputError of constraints that leave the window unbounded, as its own type: a caller that
/// made the constraints up from its settings can add which setting closes the window.
class UnboundedWindowError : public InputError
{
public:
  using InputError::InputError;
};

/// How a Window's error messages name the constraints it was given, for a caller that assembles
/// them from several sources (a rectangle's sides and a user's constraints, say).
struct ConstraintNames
{
  /// Each[i] names constraint i ("the WindowBounds side x > xmin"); a constraint without an
  /// entry, or with an empty one, is "window constraint i".
  std::vector<std::string> Each;
  /// All the constraints together, the subject of "... have no interior point in common"
  /// ("WindowBounds and the 2 window constraints"); empty: "the N window constraints".
  std::string All;
};

class Window
{
public:
  /// Throws InputError for a constraint with a NaN/Inf coefficient or a == b == 0 (naming it, by
  /// default as "window constraint i"), and for an empty or unbounded intersection. O(n log n)
  /// for a window with an interior (constraint_sweep.h: 10^5 constraints in some 0.1 s); an
  /// empty or unbounded one is named by a test of every pair, O(n^2).
  explicit Window(const std::vector<HalfPlane>& constraints, const ConstraintNames& names = {});

  /// xmin < x < xmax, ymin < y < ymax, its sides named owner + " side y > ymin" + note etc. for
  /// messages ("the rectangle's side y > ymin", "the WindowBounds side x < xmax").
  /// Throws InputError unless xmin < xmax and ymin < ymax.
  static Window Rectangle(double xmin,
    double xmax,
    double ymin,
    double ymax,
    const std::string& owner = "the rectangle's",
    const std::string& note = std::string());

  /// The effective (non-redundant) constraints, ordered so that their edges run anticlockwise
  /// around the window: edge k lies on constraint k and runs from vertex k to vertex k+1. Each is
  /// the input's constraint scaled by a power of two so that max(|a|, |b|) lies in [1, 2): the
  /// same half-plane (exactly, unless c is some 1e300 times smaller than a and b and underflows).
  const std::vector<HalfPlane>& EffectiveConstraints() const { return this->Effective; }
  /// For each effective constraint, its index in the constructor's input.
  const std::vector<std::size_t>& EffectiveIds() const { return this->EffectiveInputIds; }
  /// Constraint `inputId` of the constructor's input as the caller named it (ConstraintNames),
  /// else "window constraint i": for messages.
  std::string ConstraintName(std::size_t inputId) const;
  /// The names of the effective constraints, in their order, for a window made of them
  /// (a scaled copy, or one cut down further) to name them as this one does.
  ConstraintNames EffectiveNames() const;
  /// Indices (in the constructor's input) of the constraints found redundant.
  const std::vector<std::size_t>& RedundantIds() const { return this->RedundantInputIds; }
  /// Window corners, anticlockwise; vertex k is where constraint k-1 meets constraint k.
  const std::vector<Point2>& Vertices() const { return this->Corners; }
  /// The corners' bounding box.
  Box2 Bounds() const { return BoundsOf(this->Corners.data(), this->Corners.size()); }

  /// Whether p satisfies every effective constraint strictly (exactly evaluated).
  bool Contains(const Point2& p) const;
  /// Reflection of p in the line of effective constraint k (the "virtual point" of section 1.2).
  Point2 Reflect(const Point2& p, std::size_t k) const;
  double Area() const;
  bool IsAxisAlignedRectangle() const;

  /// The largest corner coordinate in magnitude, max |x|, |y| over the corners.
  double Reach() const;
  /// The exponent e of the power of two 2^e that brings the window's largest corner coordinate
  /// (in magnitude) into [1, 2), when that coordinate lies outside [2^-128, 2^128]; 0 otherwise.
  /// Points and window scaled by 2^e (ScaledByPowerOfTwo) have the same tessellation, exactly
  /// (a product by a power of two is exact while nothing overflows or underflows), and stay
  /// within the range where the tile derivation's window decisions are exact
  /// (window_predicates.h): a caller with coordinates of some 1e100, or 1e-100, scales first.
  int RangeScaleExponent() const;
  /// This window with every point scaled by 2^exponent (x < xmax becomes x < xmax * 2^exponent).
  /// Throws InputError when a constraint's c would lose bits (a line through the origin's
  /// neighbourhood, some 1e-300 from it, in a window of the opposite scale).
  Window ScaledByPowerOfTwo(int exponent) const;

  /// Whether every point within `error` of c in each coordinate lies strictly inside the window,
  /// by a test against a box inside it: true only when that is certain, false when the test
  /// cannot tell (also for every point when the window is not an axis-aligned rectangle). A few
  /// comparisons instead of an exact test per constraint, for the many points far from the
  /// window's edges.
  bool CertainlyContains(const Point2& c, double error) const
  {
    return c.x - error > this->Interior.XMin && c.x + error < this->Interior.XMax &&
      c.y - error > this->Interior.YMin && c.y + error < this->Interior.YMax;
  }

private:
  std::vector<HalfPlane> Effective;
  std::vector<std::size_t> EffectiveInputIds;
  std::vector<std::string> InputNames; ///< ConstraintNames::Each as given
  std::vector<std::size_t> RedundantInputIds;
  std::vector<Point2> Corners;
  Box2 Interior; ///< CertainlyContains' box (empty, so that it never passes, if not a rectangle)
};

/// The exponent e of the power of two 2^e that brings reach (a largest coordinate magnitude) into
/// [1, 2) when it lies outside [2^-128, 2^128]; 0 inside, or for 0 (Window::RangeScaleExponent).
int RangeScaleExponentOf(double reach);

/// Points scaled by 2^exponent beside a window scaled by Window::RangeScaleExponent's exponent
/// (whose corners then lie within |x|, |y| < 2). Exact, except where it cannot be: a coordinate
/// that would overflow belongs to a point far outside the window, and becomes 4 of its sign (still
/// outside: the point is rejected as before); a nonzero coordinate that would fall below the
/// normal doubles and lose bits is an InputError naming the point (the points then span more
/// orders of magnitude than the doubles hold around the window's scale).
void ScalePointsByPowerOfTwo(std::vector<Point2>& points, int exponent);

/// Scales window and points together by 2^Window::RangeScaleExponent() (nothing when it is 0),
/// so that a tessellation of them keeps its window decisions within their exact range; returns
/// the exponent, with which a caller scales the tiles back (ScaleByPowerOfTwo(TileMesh&, -e)).
int ScaleIntoExactRange(Window& window, std::vector<Point2>& points);

/// After ScaleIntoExactRange (its exponent given, for the message): throws InputError naming the
/// first point inside the window with a nonzero coordinate below 2^-200 (some 6e-61) of the
/// window's reach (its largest corner coordinate). Its bisectors meet the window lines in
/// products that fall below the doubles, and the tiles' window decisions (window_predicates.h)
/// are then not exact: points at 1e-200 and 0.0375 in a window of 0.1 got a tile of 3 sides
/// instead of 4, with no message. No scaling helps (the point spans too many orders of
/// magnitude beside the window). Points outside the window are rejected anyway and not checked.
void CheckPointsInExactRange(const Window& window, const std::vector<Point2>& points, int exponent);

/// 2^-200 of the window's reach: CheckPointsInExactRange's floor.
double ExactRangeFloor(const Window& window);

/// Whether p has a nonzero coordinate below floor in magnitude (without branches: the batch build
/// tests every point with it while it reads them anyway).
inline bool HasCoordinateBelow(const Point2& p, double floor)
{
  return ((p.x != 0.0) & (std::fabs(p.x) < floor)) | ((p.y != 0.0) & (std::fabs(p.y) < floor));
}

/// Whether p, inside the window, has such a coordinate (CheckPointsInExactRange's test).
bool BelowExactRange(const Window& window, const Point2& p);

/// CheckPointsInExactRange's message for point k at p (in the scaled units; exponent as there).
std::string BelowExactRangeMessage(const Window& window,
  const Point2& p,
  std::size_t k,
  int exponent);

} // namespace tessera
