// The convex window: shapes, redundancy (checked against an exact rational reference), order,
// errors, exact containment and the area.
#include "constraint_sweep.h"
#include "errors.h"
#include "predicates.h"
#include "window.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

using tessera::ConstraintNames;
using tessera::HalfPlane;
using tessera::InputError;
using tessera::Point2;
using tessera::UnboundedWindowError;
using tessera::Window;

namespace
{

mpq_class Q(double x)
{
  return mpq_class(x);
}

bool inside_exact(const HalfPlane& h, const Point2& p)
{
  return Q(h.a) * Q(p.x) + Q(h.b) * Q(p.y) + Q(h.c) < 0;
}

// Throws, and the message contains `part`.
template<class F>
void expect_input_error(F f, const std::string& part)
{
  try
  {
    f();
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    return;
  }
  ADD_FAILURE() << "no InputError (expected one mentioning \"" << part << "\")";
}

struct QPoint
{
  mpq_class x, y;
};

// Exact reference: the corners of the closed window are the pairwise crossings satisfying every
// constraint non-strictly; when the window has positive area, a constraint is effective iff two
// distinct corners lie on its line.
std::vector<QPoint> corners_reference(const std::vector<HalfPlane>& hs)
{
  std::vector<QPoint> corners;
  for (std::size_t i = 0; i < hs.size(); ++i)
  {
    for (std::size_t j = i + 1; j < hs.size(); ++j)
    {
      const mpq_class d = Q(hs[i].a) * Q(hs[j].b) - Q(hs[j].a) * Q(hs[i].b);
      if (d == 0)
      {
        continue;
      }
      QPoint p{ (Q(hs[i].b) * Q(hs[j].c) - Q(hs[j].b) * Q(hs[i].c)) / d,
        (Q(hs[i].c) * Q(hs[j].a) - Q(hs[j].c) * Q(hs[i].a)) / d };
      bool ok = true;
      for (const HalfPlane& h : hs)
      {
        ok = ok && Q(h.a) * p.x + Q(h.b) * p.y + Q(h.c) <= 0;
      }
      if (ok)
      {
        corners.push_back(p);
      }
    }
  }
  return corners;
}

std::set<std::size_t> effective_reference(const std::vector<HalfPlane>& hs)
{
  const std::vector<QPoint> corners = corners_reference(hs);
  std::set<std::size_t> result;
  for (std::size_t i = 0; i < hs.size(); ++i)
  {
    std::vector<QPoint> on;
    for (const QPoint& p : corners)
    {
      if (Q(hs[i].a) * p.x + Q(hs[i].b) * p.y + Q(hs[i].c) == 0)
      {
        bool seen = false;
        for (const QPoint& o : on)
        {
          seen = seen || (o.x == p.x && o.y == p.y);
        }
        if (!seen)
        {
          on.push_back(p);
        }
      }
    }
    // Of several copies of one half-plane (positive multiples), the first is the effective one.
    bool copy = false;
    for (std::size_t j = 0; j < i; ++j)
    {
      const HalfPlane& p = hs[i];
      const HalfPlane& q = hs[j];
      copy = copy ||
        (Q(p.a) * Q(q.b) == Q(q.a) * Q(p.b) && Q(p.a) * Q(q.c) == Q(q.a) * Q(p.c) &&
          Q(p.b) * Q(q.c) == Q(q.b) * Q(p.c) && Q(p.a) * Q(q.a) + Q(p.b) * Q(q.b) > 0);
    }
    if (on.size() >= 2 && !copy)
    {
      result.insert(i);
    }
  }
  return result;
}

// Independent area: all pairwise crossings inside the closed window (tolerance), sorted by angle
// about their mean, shoelace in long double.
double area_reference(const std::vector<HalfPlane>& hs)
{
  std::vector<Point2> pts;
  for (std::size_t i = 0; i < hs.size(); ++i)
  {
    for (std::size_t j = i + 1; j < hs.size(); ++j)
    {
      const long double d = (long double)hs[i].a * hs[j].b - (long double)hs[j].a * hs[i].b;
      if (std::fabs((double)d) < 1e-14)
      {
        continue;
      }
      const Point2 p{ double(((long double)hs[i].b * hs[j].c - (long double)hs[j].b * hs[i].c) / d),
        double(((long double)hs[i].c * hs[j].a - (long double)hs[j].c * hs[i].a) / d) };
      bool ok = true;
      for (const HalfPlane& h : hs)
      {
        const double scale = std::hypot(h.a, h.b);
        ok = ok && (h.a * p.x + h.b * p.y + h.c) / scale < 1e-9;
      }
      if (ok)
      {
        pts.push_back(p);
      }
    }
  }
  double mx = 0, my = 0;
  for (const Point2& p : pts)
  {
    mx += p.x / pts.size();
    my += p.y / pts.size();
  }
  std::sort(pts.begin(),
    pts.end(),
    [&](const Point2& p, const Point2& q)
    { return std::atan2(p.y - my, p.x - mx) < std::atan2(q.y - my, q.x - mx); });
  long double s = 0;
  for (std::size_t k = 0; k < pts.size(); ++k)
  {
    const Point2& p = pts[k];
    const Point2& q = pts[(k + 1) % pts.size()];
    s += (long double)p.x * q.y - (long double)q.x * p.y;
  }
  return double(s / 2);
}

// Structural checks every window must pass.
void check_structure(const Window& w, const std::vector<HalfPlane>& input)
{
  const auto& eff = w.EffectiveConstraints();
  const auto& ids = w.EffectiveIds();
  const auto& red = w.RedundantIds();
  const auto& v = w.Vertices();
  ASSERT_EQ(eff.size(), ids.size());
  ASSERT_EQ(v.size(), eff.size());
  ASSERT_GE(v.size(), 3u);
  EXPECT_EQ(ids.size() + red.size(), input.size());
  std::set<std::size_t> all(ids.begin(), ids.end());
  all.insert(red.begin(), red.end());
  EXPECT_EQ(all.size(), input.size());
  for (std::size_t k = 0; k < eff.size(); ++k)
  {
    // The input's constraint scaled by a power of two: max(|a|, |b|) in [1, 2).
    const HalfPlane& in = input[ids[k]];
    const int e = std::ilogb(std::max(std::fabs(in.a), std::fabs(in.b)));
    EXPECT_EQ(eff[k].a, std::ldexp(in.a, -e));
    EXPECT_EQ(eff[k].b, std::ldexp(in.b, -e));
    EXPECT_EQ(eff[k].c, std::ldexp(in.c, -e));
    // Anticlockwise and convex.
    const Point2& p = v[k];
    const Point2& q = v[(k + 1) % v.size()];
    const Point2& r = v[(k + 2) % v.size()];
    EXPECT_EQ(tessera::orient2d(p, q, r), 1);
    // Edge k runs from vertex k to vertex k + 1 on constraint k: nearly zero there.
    const double scale = std::hypot(eff[k].a, eff[k].b);
    const double extent =
      1.0 + std::max(std::fabs(p.x) + std::fabs(p.y), std::fabs(q.x) + std::fabs(q.y));
    EXPECT_LT(std::fabs(eff[k].a * p.x + eff[k].b * p.y + eff[k].c) / scale, 1e-12 * extent);
    EXPECT_LT(std::fabs(eff[k].a * q.x + eff[k].b * q.y + eff[k].c) / scale, 1e-12 * extent);
    // The edge's direction (-b, a) runs from vertex k to vertex k + 1.
    EXPECT_GT((q.x - p.x) * -eff[k].b + (q.y - p.y) * eff[k].a, 0.0);
  }
}

std::vector<HalfPlane> unit_square_constraints()
{
  return { { -1, 0, 0 }, { 1, 0, -1 }, { 0, -1, 0 }, { 0, 1, -1 } };
}

} // namespace

TEST(Window, Rectangle)
{
  const Window w = Window::Rectangle(-2, 3, 1, 5);
  ASSERT_EQ(w.Vertices().size(), 4u);
  const Point2 expected[4] = { { -2, 1 }, { 3, 1 }, { 3, 5 }, { -2, 5 } };
  for (int k = 0; k < 4; ++k)
  {
    EXPECT_EQ(w.Vertices()[k], expected[k]) << k;
  }
  EXPECT_TRUE(w.RedundantIds().empty());
  EXPECT_TRUE(w.IsAxisAlignedRectangle());
  EXPECT_DOUBLE_EQ(w.Area(), 20.0);
  EXPECT_TRUE(w.Contains({ 0, 2 }));
  EXPECT_FALSE(w.Contains({ -2, 2 })); // on the boundary: not strictly inside
  EXPECT_FALSE(w.Contains({ 3, 5 }));
  EXPECT_FALSE(w.Contains({ 4, 2 }));
  EXPECT_TRUE(w.Contains({ std::nextafter(-2.0, 0.0), std::nextafter(5.0, 0.0) }));
  // Reflections in the four sides.
  const Point2 p{ 0, 2 };
  EXPECT_EQ(w.Reflect(p, 0), (Point2{ 0, 0 }));
  EXPECT_EQ(w.Reflect(p, 1), (Point2{ 6, 2 }));
  EXPECT_EQ(w.Reflect(p, 2), (Point2{ 0, 8 }));
  EXPECT_EQ(w.Reflect(p, 3), (Point2{ -4, 2 }));
  check_structure(w, w.EffectiveConstraints());
}

TEST(Window, RectangleRejectsBadBounds)
{
  expect_input_error([] { Window::Rectangle(1, 1, 0, 1); }, "empty");
  expect_input_error([] { Window::Rectangle(0, 1, 2, 1); }, "empty");
  expect_input_error([] { Window::Rectangle(std::nan(""), 1, 0, 1); }, "xmin");
  expect_input_error(
    [] { Window::Rectangle(0, 1, 0, std::numeric_limits<double>::infinity()); }, "ymax");
}

TEST(Window, TriangleInAnyOrder)
{
  // x > 0, y > 0, x + y < 1, given clockwise.
  const std::vector<HalfPlane> hs = { { 0, -1, 0 }, { -1, 0, 0 }, { 1, 1, -1 } };
  const Window w(hs);
  check_structure(w, hs);
  EXPECT_EQ(w.EffectiveIds(), (std::vector<std::size_t>{ 0, 2, 1 }));
  EXPECT_EQ(w.Vertices()[0], (Point2{ 0, 0 }));
  EXPECT_EQ(w.Vertices()[1], (Point2{ 1, 0 }));
  EXPECT_EQ(w.Vertices()[2], (Point2{ 0, 1 }));
  EXPECT_DOUBLE_EQ(w.Area(), 0.5);
  EXPECT_FALSE(w.IsAxisAlignedRectangle());
  EXPECT_TRUE(w.Contains({ 0.25, 0.25 }));
  EXPECT_FALSE(w.Contains({ 0.5, 0.5 }));
  EXPECT_TRUE(w.Contains({ 0.5, std::nextafter(0.5, 0.0) }));
}

TEST(Window, RedundantConstraintsAreReported)
{
  std::vector<HalfPlane> hs = unit_square_constraints();
  hs.push_back({ 1, 1, -2 });   // 4: touches the corner (1, 1) only
  hs.push_back({ 1, 0, -5 });   // 5: x < 5, far outside
  hs.push_back({ -1, -1, -3 }); // 6: x + y > -3
  hs.push_back({ 1, -1, -1 });  // 7: x - y < 1: touches the corner (1, 0)
  hs.push_back({ 1, 1, -1.5 }); // 8: x + y < 1.5: cuts the corner (1, 1) off
  const Window w(hs);
  check_structure(w, hs);
  EXPECT_EQ(w.RedundantIds(), (std::vector<std::size_t>{ 4, 5, 6, 7 }));
  EXPECT_EQ(w.EffectiveIds(), (std::vector<std::size_t>{ 0, 2, 1, 8, 3 }));
  EXPECT_DOUBLE_EQ(w.Area(), 1.0 - 0.125);
}

TEST(Window, DuplicatedConstraintsKeepTheFirst)
{
  std::vector<HalfPlane> hs = unit_square_constraints();
  hs.push_back({ 1, 0, -1 });                       // 4: copy of 1
  hs.push_back({ 2, 0, -2 });                       // 5: scaled copy of 1
  hs.insert(hs.begin(), HalfPlane{ 0.5, 0, -0.5 }); // 0: scaled copy of (now) 2, given first
  const Window w(hs);
  check_structure(w, hs);
  EXPECT_EQ(w.RedundantIds(), (std::vector<std::size_t>{ 2, 5, 6 }));
  EXPECT_EQ(w.EffectiveIds(), (std::vector<std::size_t>{ 0, 4, 1, 3 }));
  EXPECT_DOUBLE_EQ(w.Area(), 1.0);
}

// An area that is a double is given, though twice it is not (the shoelace's terms sum to twice
// the area: a square of side 1.3e154 was infinite); one that is not is infinite, not NaN.
TEST(Window, AreaNearTheLargestDouble)
{
  const double side = 1.3e154;
  EXPECT_EQ(Window::Rectangle(0.0, side, 0.0, side).Area(), side * side);
  EXPECT_EQ(Window::Rectangle(-side, side, -side, side).Area(), HUGE_VAL);
  // A triangle: its one fan term is twice its area, which is not a double here.
  const double leg = 1.5e154;
  const Window triangle({ { -1.0, 0.0, 0.0 }, { 0.0, -1.0, 0.0 }, { 1.0, 1.0, -leg } });
  EXPECT_DOUBLE_EQ(triangle.Area(), 0.5 * leg * leg);
  EXPECT_EQ(Window::Rectangle(-1e300, 1e300, -1e300, 1e300).Area(), HUGE_VAL);
}

TEST(Window, EmptyWindows)
{
  std::vector<HalfPlane> hs = unit_square_constraints();
  hs.push_back({ 1, 1, 3 }); // x + y < -3: misses the square
  expect_input_error([&] { Window w(hs); }, "empty");
  // Parallel sides with no room between them (zero width) or crossed.
  expect_input_error(
    [] {
      Window w({ { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, -1 }, { 0, -1, 0 } });
    },
    "empty");
  expect_input_error(
    [] {
      Window w({ { 1, 0, 1 }, { -1, 0, 0 }, { 0, 1, -1 }, { 0, -1, 0 } });
    },
    "empty");
  // A triangle pointing the wrong way: x < 0, y < 0, x + y > 1.
  expect_input_error([] { Window w({ { 1, 0, 0 }, { 0, 1, 0 }, { -1, -1, 1 } }); }, "empty");
  // Three lines through one point: zero area.
  expect_input_error([] { Window w({ { 1, 0, 0 }, { 0, 1, 0 }, { -1, -1, 0 } }); }, "empty");
}

TEST(Window, UnboundedWindows)
{
  expect_input_error([] { Window w(std::vector<HalfPlane>{}); }, "unbounded");
  expect_input_error([] { Window w({ { 1, 0, 0 } }); }, "unbounded");
  expect_input_error([] { Window w({ { 1, 0, 0 }, { 0, 1, 0 } }); }, "unbounded");
  // A strip.
  expect_input_error([] { Window w({ { 1, 0, -1 }, { -1, 0, 0 } }); }, "unbounded");
  // All normals in a half-plane.
  expect_input_error(
    [] {
      Window w({ { 1, 0, -1 }, { 0, 1, -1 }, { 1, 1, -5 }, { 1, -0.5, -2 } });
    },
    "unbounded");
  // Three sides of a square.
  expect_input_error([] { Window w({ { -1, 0, 0 }, { 1, 0, -1 }, { 0, -1, 0 } }); }, "unbounded");
  // Of their own type (an InputError), for a caller that says which setting closes the window;
  // an empty window is not one.
  EXPECT_THROW(Window w({ { 1, 0, 0 } }), UnboundedWindowError);
  EXPECT_THROW(Window w(std::vector<HalfPlane>{}), UnboundedWindowError);
  try
  {
    Window w({ { 1, 0, 1 }, { -1, 0, 1 }, { 0, 1, -1 }, { 0, -1, 0 } }); // x < -1 and x > 1
    ADD_FAILURE() << "an empty window was taken";
  }
  catch (const UnboundedWindowError&)
  {
    ADD_FAILURE() << "an empty window called unbounded";
  }
  catch (const InputError&)
  {
  }
}

TEST(Window, BadConstraintsNameTheirIndex)
{
  std::vector<HalfPlane> hs = unit_square_constraints();
  hs.push_back({ 1, std::nan(""), 0 });
  expect_input_error([&] { Window w(hs); }, "constraint 4 has a NaN");
  hs.back() = { 1, 0, std::numeric_limits<double>::infinity() };
  expect_input_error([&] { Window w(hs); }, "window constraint 4 has an infinite coefficient");
  hs.back() = { 0, 0, -1 };
  expect_input_error([&] { Window w(hs); }, "constraint 4 has a == b == 0");
  hs.back() = { 1, 1, 1 };
  expect_input_error(
    [&] { Window w(hs); }, "window is empty: the 5 window constraints have no interior point");
}

// A caller that assembles the constraints (a rectangle's four sides, then a user's) names them in
// errors as its user knows them; unnamed ones keep their index.
TEST(Window, ErrorsUseTheCallersNames)
{
  std::vector<HalfPlane> hs = unit_square_constraints();
  ConstraintNames names;
  names.Each = { "side 0", "side 1", "side 2", "side 3", "user constraint 0" };
  names.All = "the sides and the 1 user constraint";
  hs.push_back({ 0, 0, -1 });
  expect_input_error([&] { Window w(hs, names); }, "user constraint 0 has a == b == 0");
  hs.back() = { 1, 1, 1 };
  expect_input_error([&] { Window w(hs, names); },
    "window is empty: the sides and the 1 user constraint have no interior point in common");
  hs.back() = { 1, 0, 1 }; // x < -1, against the square's x > 0
  expect_input_error([&] { Window w(hs, names); }, " and user constraint 0 (a = 1");
  names.Each.pop_back();
  expect_input_error([&] { Window w(hs, names); }, " and window constraint 4 (a = 1");
}

TEST(Window, RedundancyMatchesExactReference)
{
  // Small-integer coefficients: many lines through common corners, parallels and duplicates.
  std::mt19937_64 rng(21);
  std::uniform_int_distribution<int> coef(-3, 3);
  int windows = 0, redundant = 0;
  for (int trial = 0; trial < 1500; ++trial)
  {
    std::vector<HalfPlane> hs = unit_square_constraints();
    // Scale the square to [0, 4]^2 so that corners stay integer-ish.
    for (HalfPlane& h : hs)
    {
      h.c *= 4;
    }
    const int extra = 1 + trial % 8;
    for (int k = 0; k < extra; ++k)
    {
      HalfPlane h{ double(coef(rng)), double(coef(rng)), 0.0 };
      if (h.a == 0 && h.b == 0)
      {
        h.a = 1;
      }
      // Mostly lines near the square's centre (2, 2), which keep it on their inner side.
      h.c = -(2 * h.a + 2 * h.b) - double(std::uniform_int_distribution<int>(-1, 8)(rng));
      hs.push_back(h);
    }
    std::shuffle(hs.begin(), hs.end(), rng);
    std::set<std::size_t> expected;
    bool threw = false;
    try
    {
      const Window w(hs);
      check_structure(w, hs);
      expected = effective_reference(hs);
      EXPECT_EQ(std::set<std::size_t>(w.EffectiveIds().begin(), w.EffectiveIds().end()), expected);
      EXPECT_NEAR(w.Area(), area_reference(hs), 1e-12 * 16);
      ++windows;
      redundant += int(w.RedundantIds().size());
    }
    catch (const InputError& e)
    {
      threw = true;
      // Then the exact closed intersection is empty or has zero area: its corners are collinear.
      const std::vector<QPoint> corners = corners_reference(hs);
      bool flat = true;
      for (std::size_t i = 0; i < corners.size() && flat; ++i)
      {
        for (std::size_t j = 0; j < corners.size() && flat; ++j)
        {
          for (std::size_t k = 0; k < corners.size() && flat; ++k)
          {
            flat = (corners[j].x - corners[i].x) * (corners[k].y - corners[i].y) -
                (corners[j].y - corners[i].y) * (corners[k].x - corners[i].x) ==
              0;
          }
        }
      }
      EXPECT_TRUE(flat) << e.what();
    }
    if (HasFailure())
    {
      ADD_FAILURE() << "trial " << trial << (threw ? " (threw)" : "");
      return;
    }
  }
  EXPECT_GT(windows, 1000);
  EXPECT_GT(redundant, 2000);
  std::printf("%d windows, %d redundant constraints\n", windows, redundant);
}

// The sweep (constraint_sweep.h) answers exactly for the windows that are bounded with an interior,
// and for no other (the pairwise test then names what is wrong), checked against exact rational
// references on small-integer constraints: many lines through common corners, parallels, copies
// (also scaled), and empty, flat and unbounded windows.
TEST(Window, TheSweepSettlesEveryBoundedWindowWithAnInteriorAndNoOther)
{
  const auto bounded = [](const std::vector<HalfPlane>& hs)
  {
    // The recession cone {d : n_i . d <= 0 for all i} is {0} unless it holds a ray along one of
    // the lines, +-(-b_i, a_i).
    for (const HalfPlane& line : hs)
    {
      for (const int s : { 1, -1 })
      {
        const mpq_class dx = -s * Q(line.b), dy = s * Q(line.a);
        bool blocked = false;
        for (const HalfPlane& h : hs)
        {
          blocked = blocked || Q(h.a) * dx + Q(h.b) * dy > 0;
        }
        if (!blocked)
        {
          return false;
        }
      }
    }
    return !hs.empty();
  };
  const auto hasInterior = [](const std::vector<HalfPlane>& hs)
  {
    // The mean of a convex polygon's corners lies strictly inside it unless it has no area.
    const std::vector<QPoint> corners = corners_reference(hs);
    if (corners.empty())
    {
      return false;
    }
    mpq_class x = 0, y = 0;
    for (const QPoint& p : corners)
    {
      x += p.x;
      y += p.y;
    }
    x /= mpq_class(static_cast<long>(corners.size()));
    y /= mpq_class(static_cast<long>(corners.size()));
    return std::all_of(hs.begin(),
      hs.end(),
      [&](const HalfPlane& h) { return Q(h.a) * x + Q(h.b) * y + Q(h.c) < 0; });
  };
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> coef(-3, 3), offset(-8, 2);
  int settled = 0, refused = 0;
  for (int trial = 0; trial < 4000; ++trial)
  {
    std::vector<HalfPlane> hs;
    const int count = 3 + trial % 9;
    for (int k = 0; k < count; ++k)
    {
      HalfPlane h{ double(coef(rng)), double(coef(rng)), double(offset(rng)) };
      if (h.a == 0 && h.b == 0)
      {
        h.b = 1;
      }
      hs.push_back(h);
      if (rng() % 5 == 0) // a copy, or a copy scaled by 2
      {
        const double scale = rng() % 2 ? 1.0 : 2.0;
        hs.push_back({ h.a * scale, h.b * scale, h.c * scale });
      }
    }
    std::shuffle(hs.begin(), hs.end(), rng);
    const std::optional<std::vector<bool>> swept = tessera::EffectiveBySweep(hs);
    const bool valid = bounded(hs) && hasInterior(hs);
    ASSERT_EQ(swept.has_value(), valid) << "trial " << trial;
    if (swept)
    {
      std::set<std::size_t> found;
      for (std::size_t i = 0; i < hs.size(); ++i)
      {
        if ((*swept)[i])
        {
          found.insert(i);
        }
      }
      ASSERT_EQ(found, effective_reference(hs)) << "trial " << trial;
    }
    (swept ? settled : refused) += 1;
  }
  EXPECT_GT(settled, 1500);
  EXPECT_GT(refused, 1500);
  std::printf("%d windows settled by the sweep, %d left to the pairwise test\n", settled, refused);
}

// A convex polygon of 10^5 sides given as constraints (tangents to a circle, in shuffled order,
// with a copy of each tenth and lines outside): each side is effective, in the angular order. The
// pairwise test took 1.2 s at 10^4.
TEST(Window, ManyConstraintsAreSortedOutInLittleTime)
{
  const std::size_t sides = 100000;
  std::vector<HalfPlane> hs;
  for (std::size_t k = 0; k < sides; ++k)
  {
    const double t = 2.0 * M_PI * static_cast<double>(k) / static_cast<double>(sides);
    hs.push_back({ std::cos(t), std::sin(t), -1.0 });
    if (k % 10 == 0)
    {
      hs.push_back(hs.back());
      hs.push_back({ std::cos(t), std::sin(t), -1.5 }); // outside the circle's tangent
    }
  }
  std::mt19937_64 rng(8);
  std::shuffle(hs.begin(), hs.end(), rng);
  ASSERT_TRUE(tessera::EffectiveBySweep(hs).has_value()); // (settled by the sweep, not the pairs)
  const Window w(hs);
  EXPECT_EQ(w.EffectiveIds().size(), sides);
  EXPECT_EQ(w.RedundantIds().size(), 2 * sides / 10);
  EXPECT_NEAR(w.Area(), M_PI, 1e-8);
}

TEST(Window, ContainsIsExact)
{
  // Random convex polygons from tangents of a circle, with redundant extra constraints; points
  // on and next to the edges. Contains must equal the exact conjunction of *all* constraints.
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0, inside = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    std::vector<HalfPlane> hs;
    const int sides = 3 + trial % 10;
    const double cx = u(rng) * 100 - 50, cy = u(rng) * 100 - 50, r = 0.1 + u(rng) * 10;
    for (int k = 0; k < sides; ++k)
    {
      const double t = 2 * M_PI * (k + 0.3 * u(rng)) / sides;
      const double a = std::cos(t), b = std::sin(t);
      const double dist = r * (k % 3 == 2 ? 3.0 : 1.0); // some far (redundant) tangents
      hs.push_back({ a, b, -(a * cx + b * cy) - dist });
    }
    // Guarantee boundedness with a far square.
    for (const HalfPlane& h : unit_square_constraints())
    {
      hs.push_back({ h.a, h.b, h.c * 1000 - 500 });
    }
    const Window w(hs);
    check_structure(w, hs);
    EXPECT_NEAR(w.Area(), area_reference(hs), 1e-10 * w.Area());
    for (int s = 0; s < 300; ++s)
    {
      Point2 p;
      if (s % 3 == 0)
      {
        p = { cx + (u(rng) - 0.5) * 8 * r, cy + (u(rng) - 0.5) * 8 * r };
      }
      else
      {
        // On (up to rounding) an edge between two corners, possibly nudged by an ulp.
        const std::size_t k = std::size_t(u(rng) * w.Vertices().size());
        const Point2& a = w.Vertices()[k];
        const Point2& b = w.Vertices()[(k + 1) % w.Vertices().size()];
        const double t = u(rng);
        p = { a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) };
        if (s % 3 == 2)
        {
          p.x = std::nextafter(p.x, u(rng) < 0.5 ? -1e300 : 1e300);
        }
      }
      bool expected = true;
      for (const HalfPlane& h : hs)
      {
        expected = expected && inside_exact(h, p);
      }
      ASSERT_EQ(w.Contains(p), expected) << "trial " << trial << " sample " << s;
      ++checked;
      inside += expected;
    }
  }
  EXPECT_GT(inside, checked / 10);
  EXPECT_LT(inside, checked - checked / 10);
}

// CertainlyContains: whenever it says yes, every point of the square of half-side `error` around
// c is strictly inside (its four corners, checked with exact rationals: the window is a
// rectangle). Rectangles of several scales and offsets (2^30, 1e-9, 1e9), written with unit and
// non-unit coefficients (the line of 3x - 1 < 0 is not a double); centres anywhere, on the edges
// and an ulp either side; errors from 0 to large. It must also say yes for most points well inside
// (it is a fast path, not a test that never passes), and never for a window that is not a
// rectangle.
TEST(Window, CertainlyContainsOnlyWhenEveryNearbyPointIsInside)
{
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  int certified = 0, wellInside = 0, wellInsideCertified = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    const double scale = trial % 4 == 0 ? 1e-9 : trial % 4 == 1 ? 1e9 : 1.0;
    const double offset = trial % 3 == 0 ? std::ldexp(1.0, 30) * scale : 0.0;
    const double k = trial % 2 == 0 ? 1.0 : 3.0; // constraint coefficients
    const double x0 = offset + u(rng) * scale, x1 = x0 + (0.5 + u(rng)) * scale;
    const double y0 = -offset - u(rng) * scale, y1 = y0 + (0.5 + u(rng)) * scale;
    const std::vector<HalfPlane> hs{
      { -k, 0, k * x0 }, { k, 0, -k * x1 }, { 0, -k, k * y0 }, { 0, k, -k * y1 }
    };
    const Window w(hs);
    for (int s = 0; s < 200; ++s)
    {
      Point2 c{ x0 + (u(rng) * 1.2 - 0.1) * (x1 - x0), y0 + (u(rng) * 1.2 - 0.1) * (y1 - y0) };
      if (s % 4 == 1)
      {
        c.x = s % 8 == 1 ? x0 : x1; // on an edge (up to k's rounding), maybe an ulp off
        c.x = std::nextafter(c.x, u(rng) < 0.5 ? -1e300 : 1e300);
      }
      const double error = s % 5 == 0 ? 0.0 : std::ldexp(u(rng), -int(u(rng) * 60)) * scale;
      const bool certain = w.CertainlyContains(c, error);
      bool exact = true;
      for (const double dx : { -1.0, 1.0 })
      {
        for (const double dy : { -1.0, 1.0 })
        {
          const mpq_class px = Q(c.x) + dx * Q(error), py = Q(c.y) + dy * Q(error);
          for (const HalfPlane& h : hs)
          {
            exact = exact && Q(h.a) * px + Q(h.b) * py + Q(h.c) < 0;
          }
        }
      }
      ASSERT_TRUE(!certain || exact) << "trial " << trial << " sample " << s;
      certified += certain;
      const bool deep = c.x > x0 + 0.01 * (x1 - x0) && c.x < x1 - 0.01 * (x1 - x0) &&
        c.y > y0 + 0.01 * (y1 - y0) && c.y < y1 - 0.01 * (y1 - y0) && error < 1e-3 * scale;
      wellInside += deep;
      wellInsideCertified += deep && certain;
    }
  }
  EXPECT_GT(certified, 0);
  EXPECT_GT(wellInsideCertified, wellInside * 9 / 10);
  // A triangle: never certain, even at its centroid with no error.
  const Window triangle({ { -1, 0, 0 }, { 0, -1, 0 }, { 1, 1, -1 } });
  EXPECT_FALSE(triangle.CertainlyContains({ 0.25, 0.25 }, 0.0));
}

TEST(Window, ExtremeCoefficients)
{
  // Constraints scaled by huge or tiny factors describe (nearly) the same window; with powers of
  // two exactly the same one.
  for (double s : { 0x1p-1000, 0x1p-498, 0x1p498, 0x1p1000, 3e-300, 1e-150, 1e150, 7e300 })
  {
    std::vector<HalfPlane> hs = unit_square_constraints();
    for (HalfPlane& h : hs)
    {
      h = { h.a * s, h.b * s, h.c * s };
    }
    hs.push_back({ s, s, -1.5 * s });
    const Window w(hs);
    check_structure(w, hs);
    EXPECT_EQ(w.RedundantIds().size(), 0u);
    EXPECT_NEAR(w.Area(), 0.875, 1e-15);
    const Point2 probes[] = { { 0.5, 0.5 },
      { 0.75, 0.75 },
      { 0.75, std::nextafter(0.75, 0.0) },
      { std::nextafter(0.75, 1.0), 0.75 },
      { 1, 0.25 },
      { 0.25, 0 } };
    for (const Point2& p : probes)
    {
      bool expected = true;
      for (const HalfPlane& h : hs)
      {
        expected = expected && inside_exact(h, p);
      }
      EXPECT_EQ(w.Contains(p), expected) << s << " " << p.x << " " << p.y;
    }
    if (std::ilogb(s) == std::log2(s))
    {
      EXPECT_TRUE(w.Contains({ 0.5, 0.5 }));
      EXPECT_FALSE(w.Contains({ 0.75, 0.75 }));
      EXPECT_TRUE(w.Contains({ 0.75, std::nextafter(0.75, 0.0) }));
    }
    // Reflection in the bottom side y > 0 (input 2).
    const std::size_t bottom =
      std::find(w.EffectiveIds().begin(), w.EffectiveIds().end(), 2u) - w.EffectiveIds().begin();
    const Point2 r = w.Reflect({ 0.5, 0.5 }, bottom);
    EXPECT_NEAR(r.x, 0.5, 1e-14);
    EXPECT_NEAR(r.y, -0.5, 1e-14);
  }
}

// RangeScaleExponent: 0 inside [2^-128, 2^128]; outside, the power of two that brings the largest
// corner coordinate into [1, 2). ScaledByPowerOfTwo scales the corners exactly and keeps which
// points are inside (tested on points scaled alike, on and off the sides).
TEST(Window, ScalingByAPowerOfTwoIntoTheExactRange)
{
  EXPECT_EQ(Window::Rectangle(0.0, 1e6, -3.0, 5.0).RangeScaleExponent(), 0);
  EXPECT_EQ(Window::Rectangle(0.0, std::ldexp(1.0, 128), 0.0, 1.0).RangeScaleExponent(), 0);
  const Window triangle({ { -1.0, 0.0, 0.0 }, { 0.0, -1.0, 0.0 }, { 1.0, 1.0, -1.0 } });
  for (const int size : { -700, -200, 129, 300, 900 })
  {
    const double s = std::ldexp(1.0, size);
    const Window big({ { -1.0, 0.0, 0.0 }, { 0.0, -1.0, 0.0 }, { 1.0, 1.0, -s } });
    const int e = big.RangeScaleExponent();
    EXPECT_EQ(e, -size) << "window of size 2^" << size;
    const Window scaled = big.ScaledByPowerOfTwo(e);
    ASSERT_EQ(scaled.Vertices().size(), triangle.Vertices().size());
    for (std::size_t k = 0; k < scaled.Vertices().size(); ++k)
    {
      EXPECT_EQ(scaled.Vertices()[k].x, triangle.Vertices()[k].x);
      EXPECT_EQ(scaled.Vertices()[k].y, triangle.Vertices()[k].y);
    }
    EXPECT_EQ(scaled.Area(), triangle.Area());
    for (const Point2 p :
      { Point2{ 0.25, 0.25 }, Point2{ 0.5, 0.5 }, Point2{ 0.0, 0.3 }, Point2{ 0.75, 0.5 } })
    {
      const Point2 atSize{ std::ldexp(p.x, size), std::ldexp(p.y, size) };
      EXPECT_EQ(big.Contains(atSize), triangle.Contains(p));
      EXPECT_EQ(scaled.Contains(p), triangle.Contains(p));
    }
  }
}

// ScalePointsByPowerOfTwo: exact where it can be; a coordinate that would overflow becomes 4 of
// its sign (outside any window scaled into [-2, 2]); NaN stays NaN (the engine names it); a
// coordinate that would lose bits below the normal doubles is an error naming the point. A
// constraint whose c would lose bits is refused likewise.
TEST(Window, ScalingPointsByAPowerOfTwo)
{
  std::vector<Point2> points = { { 0.25, -3.0 }, { 1e300, -1e300 }, { std::nan(""), 1.0 } };
  tessera::ScalePointsByPowerOfTwo(points, 100);
  EXPECT_EQ(points[0].x, std::ldexp(0.25, 100));
  EXPECT_EQ(points[0].y, std::ldexp(-3.0, 100));
  EXPECT_EQ(points[1].x, 4.0);
  EXPECT_EQ(points[1].y, -4.0);
  EXPECT_TRUE(std::isnan(points[2].x));
  EXPECT_EQ(points[2].y, std::ldexp(1.0, 100));

  std::vector<Point2> exact = { { std::ldexp(1.0, -1000), 0.0 } }; // a subnormal power of two
  tessera::ScalePointsByPowerOfTwo(exact, -60);
  EXPECT_EQ(exact[0].x, std::ldexp(1.0, -1060));
  std::vector<Point2> lossy = { { 1.0, 2.0 },
    { std::ldexp(1.0 + std::ldexp(1.0, -20), -1000), 0.0 } };
  try
  {
    tessera::ScalePointsByPowerOfTwo(lossy, -60);
    ADD_FAILURE() << "bits lost without an error";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("point 1 ("), std::string::npos) << e.what();
  }

  const Window nearOrigin({ { -1.0, 0.0, std::ldexp(1.0 + std::ldexp(1.0, -30), -1000) },
    { 1.0, 0.0, -1.0 },
    { 0.0, -1.0, 0.0 },
    { 0.0, 1.0, -1.0 } });
  EXPECT_THROW(nearOrigin.ScaledByPowerOfTwo(-60), InputError);
  // Scaled up, exactly: the same half-planes (a, b as they were, c times 2^60), vertices times
  // 2^60.
  const Window up = nearOrigin.ScaledByPowerOfTwo(60);
  ASSERT_EQ(up.EffectiveConstraints().size(), nearOrigin.EffectiveConstraints().size());
  for (std::size_t k = 0; k < up.EffectiveConstraints().size(); ++k)
  {
    const HalfPlane &h = nearOrigin.EffectiveConstraints()[k], &g = up.EffectiveConstraints()[k];
    EXPECT_EQ(g.a * h.b, g.b * h.a) << k; // (the same direction, at any normalization)
    EXPECT_EQ(g.c * h.a, std::ldexp(h.c, 60) * g.a) << k;
    EXPECT_EQ(g.c * h.b, std::ldexp(h.c, 60) * g.b) << k;
  }
  for (std::size_t k = 0; k < up.Vertices().size(); ++k)
  {
    EXPECT_EQ(up.Vertices()[k].x, std::ldexp(nearOrigin.Vertices()[k].x, 60)) << k;
    EXPECT_EQ(up.Vertices()[k].y, std::ldexp(nearOrigin.Vertices()[k].y, 60)) << k;
  }
  // The error names the constraint as its caller did, also after a scaling that succeeded (the
  // scaled window keeps the names); without names, by its index in the caller's list.
  const auto scalingError = [](const Window& window, int exponent)
  {
    try
    {
      window.ScaledByPowerOfTwo(exponent);
    }
    catch (const InputError& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  tessera::ConstraintNames names;
  names.Each = { "the left side", "the right side", "the bottom", "the top" };
  const Window named({ { -1.0, 0.0, std::ldexp(1.0 + std::ldexp(1.0, -30), -1000) },
                       { 1.0, 0.0, -1.0 },
                       { 0.0, -1.0, 0.0 },
                       { 0.0, 1.0, -1.0 } },
    names);
  EXPECT_EQ(scalingError(named, -60).rfind("the left side cannot be scaled by 2^-60", 0), 0u)
    << scalingError(named, -60);
  EXPECT_EQ(scalingError(named.ScaledByPowerOfTwo(60), -120).rfind("the left side", 0), 0u);
  EXPECT_EQ(scalingError(nearOrigin, -60).rfind("window constraint 0 cannot be scaled", 0), 0u);
  EXPECT_EQ(named.EffectiveNames().Each.size(), named.EffectiveConstraints().size());
  EXPECT_EQ(
    Window::Rectangle(0.0, 1.0, 0.0, 1.0).ConstraintName(0), "the rectangle's side y > ymin");

  // ScaleIntoExactRange: both together by the window's exponent, or neither.
  Window big = Window::Rectangle(0.0, std::ldexp(1.0, 300), 0.0, std::ldexp(1.0, 299));
  std::vector<Point2> inside = { { std::ldexp(3.0, 297), std::ldexp(1.0, 297) } };
  EXPECT_EQ(tessera::ScaleIntoExactRange(big, inside), -300);
  EXPECT_EQ(big.Vertices()[2].x, 1.0);
  EXPECT_EQ(big.Vertices()[2].y, 0.5);
  EXPECT_EQ(inside[0].x, 0.375);
  EXPECT_EQ(inside[0].y, 0.125);
  Window unit = Window::Rectangle(0.0, 1.0, 0.0, 1.0);
  std::vector<Point2> kept = { { 0.25, 0.75 } };
  EXPECT_EQ(tessera::ScaleIntoExactRange(unit, kept), 0);
  EXPECT_EQ(kept[0].x, 0.25);
  EXPECT_EQ(unit.Vertices()[2].x, 1.0);
}

// An area beyond the doubles is infinite, not NaN (inf - inf in the shoelace): CheckTilesFillWindow
// said "not the window's area -nan".
// A slanted window (no rectangle: its area is a sum of fan terms) whose area overflows is
// infinite too, as a rectangle's is (AreaNearTheLargestDouble); one that does not is half its
// legs' product.
TEST(Window, ASlantedAreaThatOverflowsIsInfinite)
{
  for (const double leg : { 1e150, 1e200 })
  {
    const Window triangle({ { -1.0, 0.0, 0.0 }, { 0.0, -1.0, 0.0 }, { 1.0, 1.0, -leg } });
    if (leg * leg / 2 < HUGE_VAL)
    {
      EXPECT_DOUBLE_EQ(triangle.Area(), 0.5 * leg * leg);
    }
    else
    {
      EXPECT_EQ(triangle.Area(), HUGE_VAL) << leg;
    }
  }
}
