// The exact predicates against exact rational arithmetic (GMP), on random, near-degenerate,
// exactly degenerate, tiny, huge and mixed-magnitude inputs. Every case is checked through the
// public function, the inline fast path, and the exact fallback alone (so the expansion and
// big-integer tiers are exercised on every input, not only where the filter fails).
#include "predicates.h"
#include "predicates_inline.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

using tessera::Point2;

namespace
{

mpq_class Q(double x)
{
  return mpq_class(x); // mpq_set_d is exact for finite doubles
}

int sgn(const mpq_class& q)
{
  return sgn(q.get_num()) == 0 ? 0 : (q > 0 ? 1 : -1);
}

int orient_ref(const Point2& a, const Point2& b, const Point2& c)
{
  const mpq_class det =
    (Q(a.x) - Q(c.x)) * (Q(b.y) - Q(c.y)) - (Q(a.y) - Q(c.y)) * (Q(b.x) - Q(c.x));
  return sgn(det);
}

int incircle_ref(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  const mpq_class adx = Q(a.x) - Q(d.x), ady = Q(a.y) - Q(d.y);
  const mpq_class bdx = Q(b.x) - Q(d.x), bdy = Q(b.y) - Q(d.y);
  const mpq_class cdx = Q(c.x) - Q(d.x), cdy = Q(c.y) - Q(d.y);
  const mpq_class det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
    (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
    (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return sgn(det);
}

int distance_ref(const Point2& p, const Point2& a, const Point2& b)
{
  const mpq_class dax = Q(a.x) - Q(p.x), day = Q(a.y) - Q(p.y);
  const mpq_class dbx = Q(b.x) - Q(p.x), dby = Q(b.y) - Q(p.y);
  return sgn(dax * dax + day * day - dbx * dbx - dby * dby);
}

int affine_ref(double a, double b, double c, const Point2& p)
{
  return sgn(Q(a) * Q(p.x) + Q(b) * Q(p.y) + Q(c));
}

struct Tally
{
  int cases = 0;
  int zeros = 0;
};

// Checks every implementation of the three point predicates on one set of points.
void check_points(const std::vector<Point2>& p, Tally& tally)
{
  ASSERT_GE(p.size(), 4u);
  const int o = orient_ref(p[0], p[1], p[2]);
  EXPECT_EQ(tessera::orient2d(p[0], p[1], p[2]), o);
  EXPECT_EQ(tessera::orient2d_fast(p[0], p[1], p[2]), o);
  EXPECT_EQ(tessera::detail::orient2d_exact(p[0], p[1], p[2]), o);

  const int ic = incircle_ref(p[0], p[1], p[2], p[3]);
  EXPECT_EQ(tessera::incircle(p[0], p[1], p[2], p[3]), ic);
  EXPECT_EQ(tessera::incircle_fast(p[0], p[1], p[2], p[3]), ic);
  EXPECT_EQ(tessera::detail::incircle_exact(p[0], p[1], p[2], p[3]), ic);

  const int dc = distance_ref(p[0], p[1], p[2]);
  EXPECT_EQ(tessera::compare_distance(p[0], p[1], p[2]), dc);
  EXPECT_EQ(tessera::compare_distance_fast(p[0], p[1], p[2]), dc);
  EXPECT_EQ(tessera::detail::compare_distance_exact(p[0], p[1], p[2]), dc);

  const int af = affine_ref(p[0].x, p[0].y, p[1].x, p[2]);
  EXPECT_EQ(tessera::affine_sign(p[0].x, p[0].y, p[1].x, p[2]), af);

  ++tally.cases;
  tally.zeros += (o == 0) + (ic == 0) + (dc == 0) + (af == 0);
}

void run(int count,
  std::uint64_t seed,
  const std::function<std::vector<Point2>(std::mt19937_64&)>& make,
  Tally& tally)
{
  std::mt19937_64 rng(seed);
  for (int i = 0; i < count; ++i)
  {
    const std::vector<Point2> p = make(rng);
    check_points(p, tally);
    if (::testing::Test::HasFailure())
    {
      ADD_FAILURE() << "first failing case: " << i;
      return;
    }
  }
}

double uniform(std::mt19937_64& rng, double lo, double hi)
{
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

double nudge(double x, int ulps)
{
  const double toward =
    ulps > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  for (int i = 0; i < std::abs(ulps); ++i)
  {
    x = std::nextafter(x, toward);
  }
  return x;
}

std::vector<Point2> random_points(std::mt19937_64& rng, double scale)
{
  std::vector<Point2> p(4);
  for (Point2& q : p)
  {
    q = { uniform(rng, -1, 1) * scale, uniform(rng, -1, 1) * scale };
  }
  return p;
}

// Lattice points on the circle x^2 + y^2 = r^2, r = 5^6 (many Pythagorean points).
const std::vector<Point2>& circle_lattice()
{
  static const std::vector<Point2> points = []
  {
    std::vector<Point2> v;
    const long long r = 15625;
    for (long long x = -r; x <= r; ++x)
    {
      const long long y2 = r * r - x * x;
      const long long y = static_cast<long long>(std::llround(std::sqrt(static_cast<double>(y2))));
      if (y * y == y2)
      {
        v.push_back({ double(x), double(y) });
        if (y != 0)
        {
          v.push_back({ double(x), double(-y) });
        }
      }
    }
    return v;
  }();
  return points;
}

std::vector<Point2> pick_distinct(std::mt19937_64& rng, const std::vector<Point2>& from, int n)
{
  std::vector<Point2> out;
  std::uniform_int_distribution<std::size_t> pick(0, from.size() - 1);
  while (static_cast<int>(out.size()) < n)
  {
    const Point2 q = from[pick(rng)];
    bool seen = false;
    for (const Point2& o : out)
    {
      seen = seen || o == q;
    }
    if (!seen)
    {
      out.push_back(q);
    }
  }
  return out;
}

} // namespace

TEST(Predicates, RandomUnitSquare)
{
  Tally t;
  run(
    5000, 1, [](std::mt19937_64& rng) { return random_points(rng, 1.0); }, t);
}

TEST(Predicates, RandomMixedScales)
{
  Tally t;
  run(
    3000,
    2,
    [](std::mt19937_64& rng)
    {
      std::vector<Point2> p(4);
      for (Point2& q : p)
      {
        q = { std::ldexp(uniform(rng, -1, 1), int(uniform(rng, -60, 60))),
          std::ldexp(uniform(rng, -1, 1), int(uniform(rng, -60, 60))) };
      }
      return p;
    },
    t);
}

TEST(Predicates, NearlyCollinearOneUlp)
{
  Tally t;
  run(
    5000,
    3,
    [](std::mt19937_64& rng)
    {
      const Point2 a{ uniform(rng, -10, 10), uniform(rng, -10, 10) };
      const Point2 b{ uniform(rng, -10, 10), uniform(rng, -10, 10) };
      const double s = uniform(rng, -2, 3);
      Point2 c{ a.x + s * (b.x - a.x), a.y + s * (b.y - a.y) };
      const int dx = int(uniform(rng, -3, 4)), dy = int(uniform(rng, -3, 4));
      c = { nudge(c.x, dx), nudge(c.y, dy) };
      // Fourth point: also near the same line, so incircle is nearly degenerate too.
      const double u = uniform(rng, -2, 3);
      const Point2 d{ nudge(a.x + u * (b.x - a.x), 1), a.y + u * (b.y - a.y) };
      return std::vector<Point2>{ a, b, c, d };
    },
    t);
}

// A transect's points, y = x / 3 rounded, with x whole and up to 10^6 apart: their differences
// are inexact where they cross binades, so orient2d's filter fails and the adaptive stages (B, C)
// decide, the full expansions rarely. Scaled by 2^k across and beyond the stages' range
// (2^-300 to 2^300), with one point's coordinates at the range's edge or just past it, where the
// expansions decide.
TEST(Predicates, TransectPointsAtEveryScale)
{
  Tally t;
  run(
    20000,
    17,
    [](std::mt19937_64& rng)
    {
      const int k = int(uniform(rng, -330, 330));
      std::vector<Point2> p(4);
      for (Point2& q : p)
      {
        const double x = std::floor(uniform(rng, 0, 1e6));
        q = { std::ldexp(x, k), std::ldexp(x / 3.0, k) };
      }
      if (uniform(rng, 0, 1) < 0.2)
      {
        const int edge = uniform(rng, 0, 1) < 0.5 ? -300 : 300;
        p[2] = { std::ldexp(nudge(1.0, int(uniform(rng, -2, 3))), edge), p[2].y };
      }
      return p;
    },
    t);
  EXPECT_GT(t.zeros, 0); // (x a multiple of 3 on both ends: exactly collinear triples occur)
}

TEST(Predicates, ExactlyCollinearIntegers)
{
  Tally t;
  std::mt19937_64 rng(4);
  for (int i = 0; i < 3000; ++i)
  {
    const double x0 = std::floor(uniform(rng, -1e6, 1e6)), y0 = std::floor(uniform(rng, -1e6, 1e6));
    const double dx = std::floor(uniform(rng, -1e3, 1e3)), dy = std::floor(uniform(rng, -1e3, 1e3));
    const double s = std::floor(uniform(rng, -50, 50)), u = std::floor(uniform(rng, -50, 50));
    const Point2 a{ x0, y0 }, b{ x0 + dx, y0 + dy }, c{ x0 + s * dx, y0 + s * dy },
      d{ x0 + u * dx, y0 + u * dy };
    EXPECT_EQ(tessera::orient2d(a, b, c), 0);
    EXPECT_EQ(tessera::incircle(a, b, c, d), 0);
    check_points({ a, b, c, d }, t);
  }
}

TEST(Predicates, GridCircleCocircular)
{
  Tally t;
  std::mt19937_64 rng(5);
  const auto& circle = circle_lattice();
  ASSERT_GT(circle.size(), 40u);
  for (int i = 0; i < 3000; ++i)
  {
    std::vector<Point2> p = pick_distinct(rng, circle, 4);
    // Scale by a power of two (exact) and translate by a lattice offset: still co-circular.
    const int scale = int(uniform(rng, -40, 40));
    const double offset = std::floor(uniform(rng, -1e9, 1e9));
    for (Point2& q : p)
    {
      q = { std::ldexp(q.x + offset, scale), std::ldexp(q.y - offset, scale) };
    }
    EXPECT_EQ(tessera::incircle(p[0], p[1], p[2], p[3]), 0);
    EXPECT_EQ(tessera::incircle_fast(p[0], p[1], p[2], p[3]), 0);
    check_points(p, t);
  }
}

TEST(Predicates, GridCirclePerturbedOneUlp)
{
  Tally t;
  run(
    3000,
    6,
    [](std::mt19937_64& rng)
    {
      std::vector<Point2> p = pick_distinct(rng, circle_lattice(), 4);
      const double offset = std::ldexp(1.0, 30);
      for (Point2& q : p)
      {
        q = { q.x * 1e-3 + offset, q.y * 1e-3 + offset }; // rounded: nearly co-circular
      }
      const int which = int(uniform(rng, 0, 4));
      p[which].x = nudge(p[which].x, int(uniform(rng, -2, 3)));
      p[which].y = nudge(p[which].y, int(uniform(rng, -2, 3)));
      return p;
    },
    t);
}

TEST(Predicates, Offset2To30TinySteps)
{
  // Points 2^30 + small multiples of 2^-20: the filter fails on most and many are degenerate.
  Tally t;
  run(
    5000,
    7,
    [](std::mt19937_64& rng)
    {
      std::vector<Point2> p(4);
      const double base = std::ldexp(1.0, 30);
      for (Point2& q : p)
      {
        q = { base + std::ldexp(std::floor(uniform(rng, -4, 4)), -20),
          base + std::ldexp(std::floor(uniform(rng, -4, 4)), -20) };
      }
      return p;
    },
    t);
  EXPECT_GT(t.zeros, 1000);
}

TEST(Predicates, GridTierAtItsRangeLimits)
{
  // Small-integer points scaled by 2^k: the points lie on a power-of-two grid, so the grid tier
  // answers while the grid unit stays within its range, and the expansions (or big integers)
  // beyond. Either way the sign must be GMP's, degenerate or not.
  std::mt19937_64 rng(12);
  Tally t;
  for (const int k :
    { -280, -220, -160, -151, -150, -149, -100, 0, 100, 140, 149, 150, 151, 200, 260 })
  {
    for (int i = 0; i < 300; ++i)
    {
      std::vector<Point2> p(4);
      for (Point2& q : p)
      {
        q = { std::ldexp(std::floor(uniform(rng, -6, 7)), k),
          std::ldexp(std::floor(uniform(rng, -6, 7)), k) };
      }
      check_points(p, t);
    }
  }
  EXPECT_GT(t.zeros, 100);
}

TEST(Predicates, SquareLatticeExactlyDegenerate)
{
  // Four corners of any lattice square or rectangle are co-circular; with a huge offset the
  // floating-point determinant is pure noise.
  std::mt19937_64 rng(8);
  Tally t;
  for (int i = 0; i < 3000; ++i)
  {
    const double x0 = std::floor(uniform(rng, 0, 1e6)) + std::ldexp(1.0, 40);
    const double y0 = std::floor(uniform(rng, 0, 1e6)) - std::ldexp(1.0, 40);
    const double w = std::floor(uniform(rng, 1, 100)), h = std::floor(uniform(rng, 1, 100));
    const Point2 a{ x0, y0 }, b{ x0 + w, y0 }, c{ x0 + w, y0 + h }, d{ x0, y0 + h };
    EXPECT_EQ(tessera::incircle(a, b, c, d), 0);
    EXPECT_EQ(tessera::incircle(b, d, a, c), 0);
    EXPECT_EQ(tessera::orient2d(a, b, c), 1);
    check_points({ a, b, c, d }, t);
  }
}

TEST(Predicates, TinyMagnitudes)
{
  Tally t;
  run(
    3000, 9, [](std::mt19937_64& rng) { return random_points(rng, 1e-300); }, t);
  // Subnormal coordinates.
  run(
    2000, 10, [](std::mt19937_64& rng) { return random_points(rng, 1e-310); }, t);
  // Near-degenerate at tiny scale: a co-circular lattice set scaled by 2^-1000 plus one ulp.
  run(
    2000,
    11,
    [](std::mt19937_64& rng)
    {
      std::vector<Point2> p = pick_distinct(rng, circle_lattice(), 4);
      for (Point2& q : p)
      {
        q = { std::ldexp(q.x, -1000), std::ldexp(q.y, -1000) };
      }
      if (uniform(rng, 0, 1) < 0.5)
      {
        p[3].x = nudge(p[3].x, 1);
      }
      return p;
    },
    t);
}

TEST(Predicates, HugeMagnitudes)
{
  Tally t;
  run(
    3000, 12, [](std::mt19937_64& rng) { return random_points(rng, 1e150); }, t);
  // Large enough for the floating-point determinant to overflow.
  run(
    2000, 13, [](std::mt19937_64& rng) { return random_points(rng, 1e300); }, t);
  run(
    2000,
    14,
    [](std::mt19937_64& rng)
    {
      std::vector<Point2> p = pick_distinct(rng, circle_lattice(), 4);
      for (Point2& q : p)
      {
        q = { std::ldexp(q.x, 950), std::ldexp(q.y, 950) };
      }
      if (uniform(rng, 0, 1) < 0.5)
      {
        p[1].y = nudge(p[1].y, -1);
      }
      return p;
    },
    t);
}

TEST(Predicates, MixedExtremeMagnitudes)
{
  // 1e150 next to 1e-300 in one query: the big-integer tier.
  Tally t;
  run(
    1500,
    15,
    [](std::mt19937_64& rng)
    {
      std::vector<Point2> p(4);
      for (Point2& q : p)
      {
        const double sx = uniform(rng, 0, 1) < 0.5 ? 1e150 : 1e-300;
        const double sy = uniform(rng, 0, 1) < 0.5 ? 1e-300 : 1e150;
        q = { uniform(rng, -1, 1) * sx, uniform(rng, -1, 1) * sy };
      }
      return p;
    },
    t);
  // Degenerate only up to the tiny coordinates: their contribution decides the sign.
  std::mt19937_64 rng(16);
  for (int i = 0; i < 1000; ++i)
  {
    const double big = std::floor(uniform(rng, 1, 1000)) * 1e150;
    const double tiny = uniform(rng, -1, 1) * 1e-300;
    // a lies off the line y = x through b and c by a tiny amount only.
    const Point2 a{ 0, tiny }, b{ big, big }, c{ 2 * big, 2 * big };
    EXPECT_EQ(tessera::orient2d(a, b, c), tiny > 0 ? 1 : -1);
    EXPECT_EQ(tessera::orient2d(Point2{ 0, 0 }, b, c), 0);
    const Point2 d{ tiny, 0 };
    check_points({ a, b, c, d }, t);
    check_points({ d, c, b, a }, t);
    // A square of side 1e-300 far from the origin is still co-circular.
    const Point2 s0{ big, 0 }, s1{ big, 1e-300 }, s2{ nudge(big, 1), 1e-300 },
      s3{ nudge(big, 1), 0 };
    EXPECT_EQ(tessera::incircle(s0, s1, s2, s3), 0);
    check_points({ s0, s1, s2, s3 }, t);
  }
}

TEST(Predicates, SymmetriesOfOrientAndIncircle)
{
  std::mt19937_64 rng(17);
  for (int i = 0; i < 2000; ++i)
  {
    // Four lattice points of a circle, moved near (0.3, -0.7) and shrunk (inexactly: nearly
    // cocircular), the fourth then nudged by up to an ulp: signs of every kind.
    std::vector<Point2> p = pick_distinct(rng, circle_lattice(), 4);
    for (Point2& q : p)
    {
      q.x = q.x * 1e-7 + 0.3;
      q.y = q.y * 1e-7 - 0.7;
    }
    p[3].x = nudge(p[3].x, int(uniform(rng, -1, 2)));
    const int o = tessera::orient2d(p[0], p[1], p[2]);
    EXPECT_EQ(o, orient_ref(p[0], p[1], p[2])) << "case " << i;
    EXPECT_EQ(tessera::orient2d(p[1], p[2], p[0]), o);
    EXPECT_EQ(tessera::orient2d(p[1], p[0], p[2]), -o);
    const int ic = tessera::incircle(p[0], p[1], p[2], p[3]);
    EXPECT_EQ(ic, incircle_ref(p[0], p[1], p[2], p[3])) << "case " << i;
    EXPECT_EQ(tessera::incircle(p[1], p[2], p[0], p[3]), ic);
    EXPECT_EQ(tessera::incircle(p[1], p[0], p[2], p[3]), -ic);
    const int dc = tessera::compare_distance(p[0], p[1], p[2]);
    EXPECT_EQ(dc, distance_ref(p[0], p[1], p[2])) << "case " << i;
    EXPECT_EQ(tessera::compare_distance(p[0], p[2], p[1]), -dc);
  }
}

TEST(Predicates, ConventionsOnSimpleCases)
{
  const Point2 o{ 0, 0 }, x{ 1, 0 }, y{ 0, 1 };
  EXPECT_EQ(tessera::orient2d(o, x, y), 1);
  EXPECT_EQ(tessera::orient2d(o, y, x), -1);
  EXPECT_EQ(tessera::orient2d(o, x, Point2{ 2, 0 }), 0);
  EXPECT_EQ(tessera::incircle(o, x, y, Point2{ 0.5, 0.5 }), 1);
  EXPECT_EQ(tessera::incircle(o, x, y, Point2{ 2, 2 }), -1);
  EXPECT_EQ(tessera::incircle(o, x, y, Point2{ 1, 1 }), 0);
  EXPECT_EQ(tessera::incircle(o, y, x, Point2{ 0.5, 0.5 }), -1);
  EXPECT_EQ(tessera::compare_distance(o, x, Point2{ 2, 0 }), -1);
  EXPECT_EQ(tessera::compare_distance(o, x, y), 0);
  EXPECT_EQ(tessera::affine_sign(1, 0, -1, Point2{ 0.5, 7 }), -1);
  EXPECT_EQ(tessera::affine_sign(1, 0, -1, Point2{ 1, 7 }), 0);
}

TEST(Predicates, AffineSignExtremes)
{
  std::mt19937_64 rng(18);
  const double scales[] = { 1e-300, 1e-160, 1e-10, 1.0, 1e10, 1e150, 1e300, 4e-320 };
  for (int i = 0; i < 5000; ++i)
  {
    auto pick = [&]
    { return scales[std::uniform_int_distribution<int>(0, 7)(rng)] * uniform(rng, -1, 1); };
    const double a = pick(), b = pick();
    const Point2 p{ pick(), pick() };
    // c cancels a * x + b * y up to rounding: the exact sign depends on the product's low bits.
    double c = -(a * p.x + b * p.y);
    if (!std::isfinite(c))
    {
      c = pick();
    }
    if (uniform(rng, 0, 1) < 0.3)
    {
      c = nudge(c, int(uniform(rng, -2, 3)));
    }
    ASSERT_EQ(tessera::affine_sign(a, b, c, p), affine_ref(a, b, c, p))
      << a << " " << b << " " << c << " " << p.x << " " << p.y;
  }
  // Exactly zero: dyadic inputs, exact in binary, with 3 * 2^e + 5 * 2^(e+1) - 13 * 2^e = 0 (at
  // subnormal, tiny, unit and huge scales; every product and c are exact doubles). One ulp of c
  // either way is no longer zero: c is negative, so towards zero the sum turns positive.
  for (const int e : { -1070, -996, 0, 1000 })
  {
    const Point2 p{ std::ldexp(1.0, e), std::ldexp(1.0, e + 1) };
    const double c = -13 * std::ldexp(1.0, e);
    ASSERT_EQ(affine_ref(3, 5, c, p), 0) << e;
    EXPECT_EQ(tessera::affine_sign(3, 5, c, p), 0) << e;
    EXPECT_EQ(tessera::affine_sign(3, 5, std::nextafter(c, 0.0), p), 1) << e;
    EXPECT_EQ(tessera::affine_sign(3, 5, std::nextafter(c, -HUGE_VAL), p), -1) << e;
  }
  EXPECT_EQ(tessera::affine_sign(0.5, 0.25, -1, Point2{ 1, 2 }), 0);
}

namespace
{
tessera::Offset2 reflection_offset(const Point2& a, double border, bool vertical)
{
  // The reflection of a in the line x = border (or y = border), as an exact offset from a.
  tessera::Offset2 o;
  const tessera::Offset2 d =
    tessera::exact_offset(vertical ? Point2{ border, 0 } : Point2{ 0, border },
      vertical ? Point2{ a.x, 0 } : Point2{ 0, a.y });
  if (vertical)
  {
    o.x = 2 * d.x;
    o.xTail = 2 * d.xTail;
  }
  else
  {
    o.y = 2 * d.y;
    o.yTail = 2 * d.yTail;
  }
  return o;
}

mpq_class QX(const tessera::Offset2& o)
{
  return Q(o.x) + Q(o.xTail);
}
mpq_class QY(const tessera::Offset2& o)
{
  return Q(o.y) + Q(o.yTail);
}

// Offset2's representation: x is the double nearest to x + xTail, i.e. the tail is at most half
// the gap from x to the next double on the tail's side (and likewise y).
bool head_is_nearest(double head, double tail)
{
  if (tail == 0)
  {
    return true;
  }
  const double next = std::nextafter(head, tail > 0 ? HUGE_VAL : -HUGE_VAL);
  return 2 * abs(Q(tail)) <= abs(Q(next) - Q(head));
}

int incircle_offsets_ref(const tessera::Offset2& a,
  const tessera::Offset2& b,
  const tessera::Offset2& c)
{
  const mpq_class adx = QX(a), ady = QY(a), bdx = QX(b), bdy = QY(b), cdx = QX(c), cdy = QY(c);
  return sgn((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
    (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
    (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady));
}
} // namespace

TEST(Predicates, OffsetsAndReflections)
{
  // Points and their exact reflections in axis-parallel lines, given as offsets from a centre
  // point: the sweep's dummy points. Many cases are exactly co-circular (a circle through a point
  // and its reflection is centred on the mirror line).
  std::mt19937_64 rng(30);
  const double scales[] = { 1.0, 1e-3, std::ldexp(1.0, 30), 1e-300, 1e150 };
  int zeros = 0;
  for (int i = 0; i < 20000; ++i)
  {
    const double s = scales[i % 5];
    const bool lattice = (i / 5) % 2 == 0;
    auto coord = [&]
    {
      return lattice ? s * std::floor(uniform(rng, -8, 8)) + (s > 1e10 ? s : 0.0)
                     : s * uniform(rng, -1, 1);
    };
    const Point2 centre{ coord(), coord() };
    std::vector<tessera::Offset2> o(3);
    for (auto& off : o)
    {
      const int kind = int(uniform(rng, 0, 3));
      // Each offset, head plus tail, is exactly the difference it stands for (GMP).
      if (kind == 0)
      {
        const Point2 q{ coord(), coord() };
        off = tessera::exact_offset(q, centre);
        ASSERT_EQ(QX(off), Q(q.x) - Q(centre.x)) << i;
        ASSERT_EQ(QY(off), Q(q.y) - Q(centre.y)) << i;
      }
      else
      {
        // The centre's reflection in x = border (kind 1) or y = border (kind 2).
        const double border = coord();
        off = reflection_offset(centre, border, kind == 1);
        ASSERT_EQ(QX(off), kind == 1 ? 2 * (Q(border) - Q(centre.x)) : mpq_class(0)) << i;
        ASSERT_EQ(QY(off), kind == 1 ? mpq_class(0) : 2 * (Q(border) - Q(centre.y))) << i;
      }
      ASSERT_TRUE(head_is_nearest(off.x, off.xTail)) << i << " " << off.x << " " << off.xTail;
      ASSERT_TRUE(head_is_nearest(off.y, off.yTail)) << i << " " << off.y << " " << off.yTail;
    }
    const int expected = incircle_offsets_ref(o[0], o[1], o[2]);
    ASSERT_EQ(tessera::incircle_offsets(o[0], o[1], o[2]), expected) << i;
    const int cross = sgn(QX(o[0]) * QY(o[1]) - QY(o[0]) * QX(o[1]));
    ASSERT_EQ(tessera::cross_sign(o[0], o[1]), cross) << i;
    zeros += expected == 0;
    // With plain points the offsets agree with incircle itself.
    if (o[0].xTail == 0 && o[0].yTail == 0 && o[1].xTail == 0 && o[1].yTail == 0 &&
      o[2].xTail == 0 && o[2].yTail == 0 && s == 1.0)
    {
      const Point2 a{ centre.x + o[0].x, centre.y + o[0].y };
      const Point2 b{ centre.x + o[1].x, centre.y + o[1].y };
      const Point2 c{ centre.x + o[2].x, centre.y + o[2].y };
      if (a.x - centre.x == o[0].x && b.x - centre.x == o[1].x && c.x - centre.x == o[2].x &&
        a.y - centre.y == o[0].y && b.y - centre.y == o[1].y && c.y - centre.y == o[2].y)
      {
        EXPECT_EQ(tessera::incircle(a, b, c, centre), expected);
      }
    }
  }
  EXPECT_GT(zeros, 1000);
}
