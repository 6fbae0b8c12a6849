// The convex window as an intersection of open half-planes a*x + b*y + c < 0.
//
// Every combinatorial decision is exact (predicates.h): which constraints are parallel, which way
// a boundary line crosses another, where along a line the crossings lie, and so which constraints
// contribute an edge of positive length. Only the corners, the reflections and the area, which are
// numbers rather than decisions, are computed in floating point.
//
// Constraint i's boundary line L_i is walked in the direction t_i = (-b_i, a_i), which keeps the
// window on the left, i.e. runs anticlockwise around it. Along t_i the value of constraint j grows
// at the rate cross(n_i, n_j) = a_i*b_j - a_j*b_i, so a non-parallel j is *entered* (becomes
// satisfied) where L_j crosses L_i if that rate is negative and *left* if it is positive:
//
//            entry of j           exit of k
//     L_i  ------+====================+------>  t_i
//                 open edge of i, if the latest entry comes strictly before the earliest exit
//
// and whether the crossing P_ik satisfies j is sign(det(rows i, k, j)) * sign(cross(n_i, n_k)).
// That test of every pair (EffectiveByPairs) names what is wrong with an empty or unbounded
// window; a window with an interior is settled first by a sweep (constraint_sweep.h), which gives
// the same answer in O(n log n).

#include "window.h"

#include "compensated_sum.h"
#include "constraint_sweep.h"
#include "errors.h"
#include "half_plane_predicates.h"
#include "predicates.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>

namespace tessera
{
namespace
{

std::string describe(const HalfPlane& h)
{
  return "(a = " + NumberText(h.a) + ", b = " + NumberText(h.b) + ", c = " + NumberText(h.c) + ")";
}

// a*b - c*d with one rounding error less than the naive formula (Kahan's algorithm).
double difference_of_products(double a, double b, double c, double d)
{
  const double cd = c * d;
  const double error = std::fma(-c, d, cd);
  const double ab = std::fma(a, b, -cd);
  return ab + error;
}

// The constraint scaled by a power of two so that max(|a|, |b|) lies in [1, 2): the same open
// half-plane, with coefficients that cannot overflow in the products below.
HalfPlane normalized(const HalfPlane& h)
{
  const int e = std::ilogb(std::max(std::fabs(h.a), std::fabs(h.b)));
  return HalfPlane{ std::ldexp(h.a, -e), std::ldexp(h.b, -e), std::ldexp(h.c, -e) };
}

// Where the lines of two normalized constraints (max(|a|, |b|) in [1, 2), as the window stores
// them) cross.
Point2 crossing(const HalfPlane& u, const HalfPlane& v)
{
  // An axis-aligned line keeps its coordinate exactly (one rounding of -c/a or -c/b), so corners
  // lie exactly on the axis-aligned sides they join, as the tile edges' crossings do.
  if (u.b == 0.0 || v.b == 0.0)
  {
    const HalfPlane& vertical = u.b == 0.0 ? u : v;
    const HalfPlane& other = u.b == 0.0 ? v : u;
    const double x = -vertical.c / vertical.a;
    return Point2{ x, -(other.a * x + other.c) / other.b }; // (other.a == 0: exactly -c/b too)
  }
  if (u.a == 0.0 || v.a == 0.0)
  {
    const HalfPlane& horizontal = u.a == 0.0 ? u : v;
    const HalfPlane& other = u.a == 0.0 ? v : u;
    const double y = -horizontal.c / horizontal.b;
    return Point2{ -(other.b * y + other.c) / other.a, y };
  }
  const double d = difference_of_products(u.a, v.b, v.a, u.b);
  return Point2{ difference_of_products(u.b, v.c, v.b, u.c) / d,
    difference_of_products(u.c, v.a, v.c, u.a) / d };
}

// The box that Window::CertainlyContains tests against, for an axis-aligned rectangle: each side
// is the constraint's line (-c / a, rounded once) moved inwards by 2^-40 of (its coordinate's
// magnitude + the rectangle's side). The rounding of that line, and that of c.x - error (or of
// c.x + error) in the test, are a few ulps of numbers of that size, far less than the margin: so
// a point that passes is strictly inside. (A result of the test's subtraction that is subnormal is
// exact.) A rectangle too small for the margin to be a normal number gets the empty box; an
// overflowing one gets infinities or NaNs, which fail every comparison.
Box2 CertainInterior(const std::vector<HalfPlane>& effective)
{
  Box2 line = Box2::Empty(); // filled below: each axis has one lower and one upper constraint
  for (const HalfPlane& h : effective)
  {
    if (h.b == 0.0)
    {
      (h.a > 0.0 ? line.XMax : line.XMin) = -h.c / h.a;
    }
    else
    {
      (h.b > 0.0 ? line.YMax : line.YMin) = -h.c / h.b;
    }
  }
  const double width = line.XMax - line.XMin, height = line.YMax - line.YMin;
  constexpr double smallest = 0x1p-960; // the margins below stay normal numbers
  if (!(width > smallest) || !(height > smallest))
  {
    return Box2::Empty();
  }
  constexpr double margin = 0x1p-40;
  return { line.XMin + margin * (std::fabs(line.XMin) + width),
    line.XMax - margin * (std::fabs(line.XMax) + width),
    line.YMin + margin * (std::fabs(line.YMin) + height),
    line.YMax - margin * (std::fabs(line.YMax) + height) };
}

// What the other constraints do along the boundary line of constraint i: whether one of them
// makes it redundant, and which of them the line enters last and leaves first (when it enters and
// leaves any). Throws InputError when one is parallel to it, facing it, with no room between.
struct AlongLine
{
  bool Dominated = false;
  bool HasEntry = false, HasExit = false;
  std::size_t Entry = 0, Exit = 0;
};

AlongLine OthersAlong(const std::vector<HalfPlane>& constraints,
  std::size_t i,
  const std::function<std::string(std::size_t)>& named)
{
  const HalfPlane& hi = constraints[i];
  AlongLine along;
  for (std::size_t j = 0; j < constraints.size() && !along.Dominated; ++j)
  {
    if (j == i)
    {
      continue;
    }
    const HalfPlane& hj = constraints[j];
    const int rate = NormalTurn(hi, hj);
    if (rate == 0)
    {
      const int offset = ParallelOffsetSign(hi, hj);
      if (SameDirection(hi, hj))
      {
        // j lies further in (its line is the tighter one), or it is the same half-plane and the
        // first of the copies keeps the edge.
        along.Dominated = offset > 0 || (offset == 0 && j < i);
      }
      else if (offset >= 0)
      {
        throw InputError("window is empty: " + named(i) + " " + describe(hi) + " and " + named(j) +
          " " + describe(hj) + " are parallel and leave no room between them");
      }
    }
    else if (rate < 0)
    {
      // Entering j. Keep the latest entry: j is later if its crossing satisfies the current one.
      if (!along.HasEntry || ValueAtCrossing(hi, hj, constraints[along.Entry]) < 0)
      {
        along.Entry = j;
      }
      along.HasEntry = true;
    }
    else
    {
      // Leaving j. Keep the earliest exit: j is earlier if its crossing satisfies the current.
      if (!along.HasExit || ValueAtCrossing(hi, hj, constraints[along.Exit]) < 0)
      {
        along.Exit = j;
      }
      along.HasExit = true;
    }
  }
  return along;
}

// Which constraints are effective, each tested against every other, O(n^2) (see the sketch at the
// top): throws InputError for a window found empty, UnboundedWindowError for one found unbounded,
// naming the constraints (named(i)).
std::vector<bool> EffectiveByPairs(const std::vector<HalfPlane>& constraints,
  const std::function<std::string(std::size_t)>& named)
{
  std::vector<bool> effective(constraints.size(), false);
  for (std::size_t i = 0; i < constraints.size(); ++i)
  {
    const AlongLine along = OthersAlong(constraints, i, named);
    if (along.Dominated)
    {
      continue;
    }
    if (!along.HasEntry || !along.HasExit)
    {
      // A ray (or the whole line) of L_i satisfies every other constraint strictly; points just
      // inside it are in the window, whose closure then contains a ray.
      throw UnboundedWindowError("window is unbounded: the boundary line of " + named(i) + " " +
        describe(constraints[i]) + " is not closed off by the other constraints" +
        (along.HasEntry || along.HasExit ? " at one end" : " at either end"));
    }
    effective[i] =
      ValueAtCrossing(constraints[i], constraints[along.Entry], constraints[along.Exit]) < 0;
  }
  return effective;
}

// Throws InputError naming the first constraint with a coefficient that is not finite or with
// a == b == 0, and UnboundedWindowError when there are no constraints.
void CheckCoefficients(const std::vector<HalfPlane>& constraints,
  const std::function<std::string(std::size_t)>& named)
{
  for (std::size_t i = 0; i < constraints.size(); ++i)
  {
    const HalfPlane& h = constraints[i];
    if (!std::isfinite(h.a) || !std::isfinite(h.b) || !std::isfinite(h.c))
    {
      throw InputError(named(i) + " has " +
        (std::isnan(h.a) || std::isnan(h.b) || std::isnan(h.c) ? "a NaN" : "an infinite") +
        " coefficient " + describe(h));
    }
    if (h.a == 0.0 && h.b == 0.0)
    {
      throw InputError(named(i) + " has a == b == 0: it is no half-plane " + describe(h));
    }
  }
  if (constraints.empty())
  {
    throw UnboundedWindowError("window is unbounded: no constraints given");
  }
}

// Anticlockwise order around a convex polygon is the angular order of the outward normals,
// starting from the first effective constraint given. No two effective normals are parallel
// and point the same way.
void SortAnticlockwise(const std::vector<HalfPlane>& constraints, std::vector<std::size_t>& ids)
{
  const AngleFrom angle(constraints[ids.front()]);
  std::sort(ids.begin() + 1,
    ids.end(),
    [&](std::size_t p, std::size_t q) { return angle(constraints[p], constraints[q]); });
}

} // namespace

Window::Window(const std::vector<HalfPlane>& constraints, const ConstraintNames& names)
  : InputNames(names.Each)
{
  const std::size_t n = constraints.size();
  const auto named = [this](std::size_t i) { return this->ConstraintName(i); };
  CheckCoefficients(constraints, named);
  // The sweep settles a bounded window with an interior in O(n log n) (10^4 constraints, as a
  // catchment outline given as constraints, took the pairs 1.2 s); the pairs name what is wrong
  // with any other.
  std::optional<std::vector<bool>> swept = EffectiveBySweep(constraints);
  const std::vector<bool> effective =
    swept ? *std::move(swept) : EffectiveByPairs(constraints, named);
  std::vector<std::size_t> ids;
  for (std::size_t i = 0; i < n; ++i)
  {
    (effective[i] ? ids : this->RedundantInputIds).push_back(i);
  }
  if (ids.size() < 3)
  {
    // A nonempty open intersection has a boundary of positive length on some constraint.
    throw InputError("window is empty: " +
      (names.All.empty() ? "the " + std::to_string(n) + " window constraints" : names.All) +
      " have no interior point in common");
  }
  SortAnticlockwise(constraints, ids);
  this->EffectiveInputIds = ids;
  for (std::size_t id : ids)
  {
    // Scaled by a power of two (the same half-plane, exactly): the tiles' constructions square
    // and multiply coefficients, which overflowed for |a|, |b| around 1e155 and underflowed
    // around 1e-200.
    this->Effective.push_back(normalized(constraints[id]));
  }
  const std::size_t m = ids.size();
  for (std::size_t k = 0; k < m; ++k)
  {
    this->Corners.push_back(crossing(this->Effective[(k + m - 1) % m], this->Effective[k]));
  }
  this->Interior =
    this->IsAxisAlignedRectangle() ? CertainInterior(this->Effective) : Box2::Empty();
}

std::string Window::ConstraintName(std::size_t inputId) const
{
  const bool given = inputId < this->InputNames.size() && !this->InputNames[inputId].empty();
  return given ? this->InputNames[inputId] : "window constraint " + std::to_string(inputId);
}

ConstraintNames Window::EffectiveNames() const
{
  ConstraintNames names;
  for (const std::size_t id : this->EffectiveInputIds)
  {
    names.Each.push_back(this->ConstraintName(id));
  }
  return names;
}

Window Window::Rectangle(double xmin,
  double xmax,
  double ymin,
  double ymax,
  const std::string& owner,
  const std::string& note)
{
  const double bounds[4] = { xmin, xmax, ymin, ymax };
  const char* names[4] = { "xmin", "xmax", "ymin", "ymax" };
  for (int i = 0; i < 4; ++i)
  {
    if (!std::isfinite(bounds[i]))
    {
      throw InputError(std::string("rectangle window: ") + names[i] + " = " +
        NumberText(bounds[i]) + " is not finite");
    }
  }
  if (!(xmin < xmax) || !(ymin < ymax))
  {
    throw InputError("rectangle window is empty: need xmin < xmax and ymin < ymax, got x in (" +
      NumberText(xmin) + ", " + NumberText(xmax) + "), y in (" + NumberText(ymin) + ", " +
      NumberText(ymax) + ")");
  }
  // Bottom, right, top, left: vertex 0 is the lower-left corner.
  ConstraintNames sides;
  for (const char* side : { "y > ymin", "x < xmax", "y < ymax", "x > xmin" })
  {
    sides.Each.push_back(owner + " side " + side + note);
  }
  return Window({ HalfPlane{ 0.0, -1.0, ymin },
                  HalfPlane{ 1.0, 0.0, -xmax },
                  HalfPlane{ 0.0, 1.0, -ymax },
                  HalfPlane{ -1.0, 0.0, xmin } },
    sides);
}

bool Window::Contains(const Point2& p) const
{
  for (const HalfPlane& h : this->Effective)
  {
    if (affine_sign(h.a, h.b, h.c, p) >= 0)
    {
      return false;
    }
  }
  return true;
}

Point2 Window::Reflect(const Point2& p, std::size_t k) const
{
  const HalfPlane& h = this->Effective.at(k); // normalized: the products below cannot overflow
  const double value = std::fma(h.a, p.x, std::fma(h.b, p.y, h.c));
  const double scale = 2.0 * value / (h.a * h.a + h.b * h.b);
  return Point2{ p.x - scale * h.a, p.y - scale * h.b };
}

namespace
{
/// The shoelace area of corners (anticlockwise), fanned from corner 0, by Neumaier's compensated
/// summation of the fan's terms (twice each triangle's area), corners taken times 2^exponent
/// (exact while nothing overflows or underflows).
double FanArea(const std::vector<Point2>& corners, int exponent)
{
  const auto at = [&](std::size_t k) {
    return Point2{ std::ldexp(corners[k].x, exponent), std::ldexp(corners[k].y, exponent) };
  };
  const Point2 o = at(0);
  CompensatedSum area;
  for (std::size_t k = 1; k + 1 < corners.size(); ++k)
  {
    const Point2 u = at(k), v = at(k + 1);
    area.Add(difference_of_products(u.x - o.x, v.y - o.y, u.y - o.y, v.x - o.x));
  }
  return 0.5 * area.Value();
}
} // namespace

double Window::Area() const
{
  // A window whose area is a double can have fan terms that are not (twice a triangle's area, of
  // corners some 1e154 and more; a square of side 1.3e154, or a triangle): then the corners are
  // scaled down by a power of two first, and the area back up, which is exact for the sum and
  // overflows only when the area does.
  const double area = FanArea(this->Corners, 0);
  if (std::isfinite(area))
  {
    return area;
  }
  int exponent = 0;
  std::frexp(this->Reach(), &exponent);
  const double scaled = std::ldexp(FanArea(this->Corners, -exponent), 2 * exponent);
  // Terms that still overflow sum to inf - inf: the area is infinite, not NaN.
  return std::isnan(scaled) ? std::numeric_limits<double>::infinity() : scaled;
}

double Window::Reach() const
{
  double largest = 0.0;
  for (const Point2& corner : this->Corners)
  {
    largest = std::max({ largest, std::fabs(corner.x), std::fabs(corner.y) });
  }
  return largest;
}

int RangeScaleExponentOf(double reach)
{
  if (!(reach > 0.0) || !std::isfinite(reach) ||
    (reach >= std::ldexp(1.0, -128) && reach <= std::ldexp(1.0, 128)))
  {
    return 0;
  }
  int exponent = 0;
  std::frexp(reach, &exponent); // reach = f * 2^exponent, f in [0.5, 1)
  return 1 - exponent;
}

int Window::RangeScaleExponent() const
{
  return RangeScaleExponentOf(this->Reach());
}

Window Window::ScaledByPowerOfTwo(int exponent) const
{
  std::vector<HalfPlane> scaled = this->Effective;
  for (std::size_t k = 0; k < scaled.size(); ++k)
  {
    const double c = scaled[k].c;
    scaled[k].c = std::ldexp(c, exponent);
    if (std::ldexp(scaled[k].c, -exponent) != c)
    {
      throw InputError(this->ConstraintName(this->EffectiveInputIds[k]) +
        " cannot be scaled by 2^" + std::to_string(exponent) +
        " exactly, as the window's scale needs: its line passes some " + NumberText(std::fabs(c)) +
        " from the origin, in a window whose corners reach " + NumberText(this->Reach()) +
        " (the window and the points span more orders of magnitude than the doubles hold around "
        "one scale)");
    }
  }
  return Window(scaled, this->EffectiveNames());
}

void ScalePointsByPowerOfTwo(std::vector<Point2>& points, int exponent)
{
  const auto scale = [exponent](double v, bool& lost)
  {
    const double scaled = std::ldexp(v, exponent);
    if (std::isinf(scaled) && std::isfinite(v))
    {
      return std::copysign(4.0, v); // far outside the scaled window, and still outside
    }
    lost = lost || (std::isfinite(v) && std::ldexp(scaled, -exponent) != v); // (NaN: named later)
    return scaled;
  };
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    bool lost = false;
    const Point2 p = points[k];
    points[k] = { scale(p.x, lost), scale(p.y, lost) };
    if (lost)
    {
      throw InputError("point " + std::to_string(k) + " (" + NumberText(p.x) + ", " +
        NumberText(p.y) + ") cannot be scaled by 2^" + std::to_string(exponent) +
        " exactly, as the window's scale needs: the points span more orders of magnitude than the "
        "doubles hold around it");
    }
  }
}

int ScaleIntoExactRange(Window& window, std::vector<Point2>& points)
{
  const int exponent = window.RangeScaleExponent();
  if (exponent != 0)
  {
    window = window.ScaledByPowerOfTwo(exponent);
    ScalePointsByPowerOfTwo(points, exponent);
  }
  return exponent;
}

double ExactRangeFloor(const Window& window)
{
  return std::ldexp(window.Reach(), -200);
}

bool BelowExactRange(const Window& window, const Point2& p)
{
  return HasCoordinateBelow(p, ExactRangeFloor(window)) && window.Contains(p);
}

std::string BelowExactRangeMessage(const Window& window,
  const Point2& p,
  std::size_t k,
  int exponent)
{
  return "point " + std::to_string(k) + " (" + NumberText(std::ldexp(p.x, -exponent)) + ", " +
    NumberText(std::ldexp(p.y, -exponent)) +
    ") has a coordinate below 2^-200 (some 6e-61) of the window's reach (its largest corner "
    "coordinate, " +
    NumberText(std::ldexp(window.Reach(), -exponent)) +
    "), though not 0: the tiles' window decisions are exact only from there up, whatever the "
    "scale; set that coordinate to 0, or move the origin, or use the Brassel-Reif sweep "
    "(ComputeThiessenSweep; the tessellation filter's Algorithm BrasselReif), which takes such "
    "points in a rectangular window";
}

void CheckPointsInExactRange(const Window& window, const std::vector<Point2>& points, int exponent)
{
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    if (BelowExactRange(window, points[k]))
    {
      throw InputError(BelowExactRangeMessage(window, points[k], k, exponent));
    }
  }
}

bool Window::IsAxisAlignedRectangle() const
{
  if (this->Effective.size() != 4)
  {
    return false;
  }
  for (const HalfPlane& h : this->Effective)
  {
    if (h.a != 0.0 && h.b != 0.0)
    {
      return false;
    }
  }
  return true;
}

} // namespace tessera
