// Minor and major ridges against the definitions of Goshtasby 2000 section 2 written out here,
// on random and analytic images; thinning, segments, removal and joining on drawn skeletons.
#include "errors.h"
#include "ridge_contours.h"
#include "ridge_extraction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{

const double Pi = std::acos(-1.0);

std::vector<double> RandomImage(int width, int height, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> level(0, 6); // few levels: plenty of ties
  std::vector<double> image(width * height);
  for (double& v : image)
  {
    v = level(rng);
  }
  return image;
}

// Equations 2-5 verbatim, (i, j) with i the column.
bool PaperMinor(const std::vector<double>& I, int w, int h, int i, int j)
{
  auto at = [&](int a, int b) { return I[b * w + a]; };
  const double c = at(i, j);
  bool minor = false;
  if (i > 0 && i < w - 1)
    minor |= at(i - 1, j) < c && at(i + 1, j) < c;
  if (j > 0 && j < h - 1)
    minor |= at(i, j - 1) < c && at(i, j + 1) < c;
  if (i > 0 && i < w - 1 && j > 0 && j < h - 1)
  {
    minor |= at(i - 1, j - 1) < c && at(i + 1, j + 1) < c;
    minor |= at(i - 1, j + 1) < c && at(i + 1, j - 1) < c;
  }
  return minor;
}

TEST(RidgeExtraction, MinorRidgesAreEquationsTwoToFive)
{
  for (unsigned seed = 1; seed <= 5; ++seed)
  {
    const int w = 23;
    const int h = 17;
    const std::vector<double> image = RandomImage(w, h, seed);
    const tessera::RidgeMasks masks = tessera::ExtractRidges(image, w, h);
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        EXPECT_EQ(masks.Minor[j * w + i] != 0, PaperMinor(image, w, h, i, j)) << i << "," << j;
        EXPECT_LE(masks.Major[j * w + i], masks.Minor[j * w + i]);
      }
    }
  }
}

TEST(RidgeExtraction, AStraightRidgeIsMajorAndAPeakIsAStarOfMinorRidges)
{
  const int w = 41;
  const int h = 41;
  std::vector<double> ridge(w * h);
  std::vector<double> peak(w * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      // Crest along row 20 rising slowly to the east: across drop 1, along change 0.01.
      ridge[j * w + i] = -(j - 20.0) * (j - 20.0) + 0.01 * i;
      peak[j * w + i] = -std::hypot(i - 20.0, j - 20.0);
    }
  }
  const tessera::RidgeMasks r = tessera::ExtractRidges(ridge, w, h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 1; i < w - 1; ++i)
    {
      EXPECT_EQ(r.Minor[j * w + i], j == 20 ? 1 : 0) << i << "," << j;
      EXPECT_EQ(r.Major[j * w + i], j == 20 ? 1 : 0) << i << "," << j;
    }
  }
  // A cone: every line through its apex along a test axis is a minor ridge (the 1-D maximum
  // across it), but the gradient there points along the line, so only the apex is major.
  const tessera::RidgeMasks p = tessera::ExtractRidges(peak, w, h);
  for (int j = 1; j < h - 1; ++j)
  {
    for (int i = 1; i < w - 1; ++i)
    {
      const bool onStar = i == 20 || j == 20 || i - 20 == j - 20 || i - 20 == 20 - j;
      EXPECT_EQ(p.Minor[j * w + i] != 0, onStar) << i << "," << j;
      EXPECT_EQ(p.Major[j * w + i] != 0, i == 20 && j == 20) << i << "," << j;
    }
  }
}

TEST(RidgeExtraction, GradientDirectionIsTheSteepestNeighbour)
{
  const int w = 5;
  const int h = 5;
  std::vector<double> image(w * h, 0.0);
  image[3 * w + 3] = -2.0; // NE neighbour of (2, 2): change 2 / sqrt(2) = 1.41
  image[2 * w + 1] = 1.3;  // W neighbour: change 1.3
  EXPECT_EQ(tessera::GradientDirection(image, w, h, 2, 2), 1);
  image[2 * w + 1] = 1.5;
  EXPECT_EQ(tessera::GradientDirection(image, w, h, 2, 2), 4);
  EXPECT_EQ(tessera::GradientDirection(std::vector<double>(w * h, 1.0), w, h, 2, 2), -1);
  EXPECT_THROW(tessera::ExtractRidges(image, w + 1, h), tessera::InputError);
}

using Mask = std::vector<std::uint8_t>;

void Draw(Mask& mask, int w, int i0, int j0, int i1, int j1)
{
  const int steps = std::max(std::abs(i1 - i0), std::abs(j1 - j0));
  for (int s = 0; s <= steps; ++s)
  {
    const int i = i0 + static_cast<int>(std::lround(double(s) * (i1 - i0) / std::max(steps, 1)));
    const int j = j0 + static_cast<int>(std::lround(double(s) * (j1 - j0) / std::max(steps, 1)));
    mask[j * w + i] = 1;
  }
}

int ComponentCount(const Mask& mask, int w, int h)
{
  std::vector<int> label(mask.size(), -1);
  int count = 0;
  for (int p = 0; p < w * h; ++p)
  {
    if (!mask[p] || label[p] >= 0)
      continue;
    std::vector<int> stack{ p };
    label[p] = count;
    while (!stack.empty())
    {
      const int q = stack.back();
      stack.pop_back();
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
        {
          const int i = q % w + di;
          const int j = q / w + dj;
          if (i < 0 || j < 0 || i >= w || j >= h || !mask[j * w + i] || label[j * w + i] >= 0)
            continue;
          label[j * w + i] = count;
          stack.push_back(j * w + i);
        }
    }
    ++count;
  }
  return count;
}

TEST(RidgeContours, ThinningKeepsComponentsAndLeavesNoRemovablePixel)
{
  std::mt19937 rng(2);
  for (int trial = 0; trial < 10; ++trial)
  {
    const int w = 50;
    const int h = 40;
    Mask mask(w * h, 0);
    // Thick random strokes.
    std::uniform_int_distribution<int> x(3, w - 4);
    std::uniform_int_distribution<int> y(3, h - 4);
    for (int stroke = 0; stroke < 4; ++stroke)
    {
      const int i0 = x(rng), j0 = y(rng), i1 = x(rng), j1 = y(rng);
      for (int t = -1; t <= 1; ++t)
      {
        Draw(mask, w, i0, j0 + t, i1, j1 + t);
      }
    }
    const int before = ComponentCount(mask, w, h);
    tessera::ThinToSkeleton(mask, w, h);
    EXPECT_EQ(ComponentCount(mask, w, h), before);
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        if (!mask[j * w + i])
          continue;
        int neighbours = 0;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di)
            neighbours += (di || dj) && i + di >= 0 && j + dj >= 0 && i + di < w && j + dj < h &&
              mask[(j + dj) * w + i + di];
        if (neighbours >= 2)
        {
          EXPECT_NE(tessera::ConnectivityNumber(mask, w, h, i, j), 1) << i << "," << j;
        }
      }
    }
  }
}

TEST(RidgeContours, BranchWithoutMajorPixelIsRemovedAndTheLineJoined)
{
  const int w = 80;
  const int h = 40;
  Mask minor(w * h, 0);
  Mask major(w * h, 0);
  Draw(minor, w, 5, 10, 74, 10);  // the ridge
  Draw(minor, w, 40, 11, 40, 30); // a branch from its middle
  major[10 * w + 20] = 1;         // one major pixel on each half of the ridge only
  major[10 * w + 60] = 1;
  tessera::RidgeContourSettings settings;
  settings.MinimumLength = 5;
  const tessera::RidgeContours c = tessera::TraceRidgeContours(minor, major, w, h, settings);
  EXPECT_EQ(c.SegmentCount, 3);
  ASSERT_EQ(c.Count(), 1);
  EXPECT_FALSE(c.Closed[0]);
  // 69 pixels, plus at most 2 sqrt(2) - 2 where thinning routes the line through the first
  // pixel of the branch (the T's corner pixels are simple and go first).
  EXPECT_GE(c.Lengths[0], 69.0 - 1e-9);
  EXPECT_LE(c.Lengths[0], 69.0 + 2 * std::sqrt(2.0) - 2 + 1e-9);
  const int first = c.Pixels[c.Offsets[0]];
  const int last = c.Pixels[c.Offsets[1] - 1];
  EXPECT_EQ(std::min(first % w, last % w), 5);
  EXPECT_EQ(std::max(first % w, last % w), 74);
}

TEST(RidgeContours, SaddlePathBetweenTwoRidgesGoesAShortCrossingStays)
{
  // Two horizontal ridges, rows 10 and 40, every pixel major, joined by vertical paths without
  // a major pixel: one at x = 30, 29 pixels long (beyond the bridge limit of 12: a saddle path),
  // and on a third ridge pair (rows 60 and 70) one 9 pixels long (within the limit: kept).
  const int w = 80;
  const int h = 80;
  Mask minor(w * h, 0);
  Draw(minor, w, 5, 10, 74, 10);
  Draw(minor, w, 5, 40, 74, 40);
  Draw(minor, w, 5, 60, 74, 60);
  Draw(minor, w, 5, 70, 74, 70);
  Mask major = minor;
  Draw(minor, w, 30, 11, 30, 39);
  Draw(minor, w, 30, 61, 30, 69);
  tessera::RidgeContourSettings settings;
  settings.MinimumLength = 5;
  settings.MaximumBridgeLength = 12;
  const tessera::RidgeContours c = tessera::TraceRidgeContours(minor, major, w, h, settings);
  // Whether some contour holds a pixel of the path at x = 30 strictly between two rows (the
  // junction pixels at the rows' ends belong to the rows).
  auto pathKept = [&](int rowFrom, int rowTo)
  {
    for (std::size_t q = 0; q < c.Pixels.size(); ++q)
    {
      const int i = c.Pixels[q] % w, j = c.Pixels[q] / w;
      if (i == 30 && j > rowFrom + 1 && j < rowTo - 1)
      {
        return true;
      }
    }
    return false;
  };
  EXPECT_FALSE(pathKept(10, 40));
  EXPECT_TRUE(pathKept(60, 70));
}

TEST(RidgeContours, CrestPieceBetweenNoiseBranchesStaysWhenTheBranchesGo)
{
  // A ridge on row 20 with major pixels only near its ends, and two noise branches without
  // major pixels leaving it at x = 25 and x = 55: the 30-pixel crest piece between them is
  // longer than the bridge limit, but once the branches are gone it is part of the ridge.
  const int w = 80;
  const int h = 40;
  Mask minor(w * h, 0);
  Mask major(w * h, 0);
  Draw(minor, w, 5, 20, 74, 20);
  Draw(minor, w, 25, 21, 25, 32);
  Draw(minor, w, 55, 19, 55, 8);
  major[20 * w + 10] = 1;
  major[20 * w + 70] = 1;
  tessera::RidgeContourSettings settings;
  settings.MinimumLength = 5;
  settings.MaximumBridgeLength = 10;
  const tessera::RidgeContours c = tessera::TraceRidgeContours(minor, major, w, h, settings);
  ASSERT_EQ(c.Count(), 1);
  EXPECT_GE(c.Lengths[0], 69.0 - 1e-9);
  EXPECT_LE(c.Lengths[0], 69.0 + 4 * std::sqrt(2.0) - 4 + 1e-9);
}

TEST(RidgeContours, JoinRulesAtATJunction)
{
  // Horizontal ridge 5..74 on row 10 and a branch rising from x = 40, all major. Longest:
  // the two halves (34 + 35) beat half + branch (35 + 20). Tangent: the halves are opposite.
  // A second picture where the branch is the longer arm: Longest joins it, Tangent does not.
  const int w = 80;
  const int h = 70;
  for (int branchLength : { 20, 55 })
  {
    Mask minor(w * h, 0);
    Draw(minor, w, 5, 10, 74, 10);
    Draw(minor, w, 40, 11, 40, 10 + branchLength);
    const Mask major = minor;
    for (auto rule : { tessera::JoinRule::Longest, tessera::JoinRule::ClosestTangent })
    {
      tessera::RidgeContourSettings settings;
      settings.Join = rule;
      settings.MinimumLength = 0;
      const tessera::RidgeContours c = tessera::TraceRidgeContours(minor, major, w, h, settings);
      ASSERT_EQ(c.Count(), 2);
      double longest = std::max(c.Lengths[0], c.Lengths[1]);
      const bool straightJoined = rule == tessera::JoinRule::ClosestTangent || branchLength == 20;
      // Joined halves: 69 pixels. Half + branch: 35 + branchLength (through the junction).
      EXPECT_NEAR(longest, straightJoined ? 69.0 : 35.0 + branchLength, 1.0)
        << "rule " << int(rule) << " branch " << branchLength;
    }
  }
}

TEST(RidgeContours, RingIsOneClosedContourAndShortPiecesAreDropped)
{
  const int w = 60;
  const int h = 60;
  Mask minor(w * h, 0);
  for (int k = 0; k < 720; ++k)
  {
    const double a = k * Pi / 360.0;
    minor[std::lround(30 + 20 * std::sin(a)) * w + std::lround(30 + 20 * std::cos(a))] = 1;
  }
  Draw(minor, w, 2, 2, 6, 2); // a 4-pixel piece
  const Mask major = minor;
  tessera::RidgeContourSettings settings;
  settings.MinimumLength = 10;
  const tessera::RidgeContours c = tessera::TraceRidgeContours(minor, major, w, h, settings);
  ASSERT_EQ(c.Count(), 1);
  EXPECT_TRUE(c.Closed[0]);
  EXPECT_NEAR(c.Lengths[0], 2 * Pi * 20, 0.1 * 2 * Pi * 20);
  EXPECT_EQ(c.ShortContourCount, 1); // the piece, counted as dropped for its length
  EXPECT_EQ(c.ShortLoopCount, 0);
  settings.MinimumLength = 0;
  const tessera::RidgeContours all = tessera::TraceRidgeContours(minor, major, w, h, settings);
  EXPECT_EQ(all.Count(), 2);
  EXPECT_EQ(all.ShortContourCount + all.ShortLoopCount, 0);
  // A loop shorter than MinimumLoopLength goes, counted apart from the short pieces.
  settings.MinimumLength = 10;
  settings.MinimumLoopLength = 2 * Pi * 20 * 1.2;
  const tessera::RidgeContours noLoop = tessera::TraceRidgeContours(minor, major, w, h, settings);
  EXPECT_EQ(noLoop.Count(), 0);
  EXPECT_EQ(noLoop.ShortContourCount, 1);
  EXPECT_EQ(noLoop.ShortLoopCount, 1);
  settings.MinimumLength = -1;
  EXPECT_THROW(tessera::TraceRidgeContours(minor, major, w, h, settings), tessera::InputError);
}

TEST(RidgeContours, SideStrandAroundHolesGoesAParallelRidgeStays)
{
  // A ridge on row 10 with a second strand on row 12 from x = 20 to 40, joined to it at x = 20,
  // 30 and 40 (two holes between the strands, as a noisy ridge band has): the long contour takes
  // one strand, the other becomes a contour of about 20 pixels beside it. A separate ridge on
  // row 30 (20 pixels off) of the same length as that strand stays.
  const int w = 80;
  const int h = 40;
  Mask minor(w * h, 0);
  Draw(minor, w, 5, 10, 74, 10);
  Draw(minor, w, 20, 12, 40, 12);
  for (int x : { 20, 30, 40 })
  {
    Draw(minor, w, x, 11, x, 11);
  }
  Draw(minor, w, 20, 30, 40, 30);
  const Mask major = minor;
  tessera::RidgeContourSettings settings;
  settings.MinimumLength = 10;
  const tessera::RidgeContours before = tessera::TraceRidgeContours(minor, major, w, h, settings);
  EXPECT_EQ(before.Count(), 3);
  EXPECT_EQ(before.SideStrandCount, 0);
  settings.SideStrandDistance = 5;
  settings.MaximumSideStrandLength = 30;
  const tessera::RidgeContours c = tessera::TraceRidgeContours(minor, major, w, h, settings);
  ASSERT_EQ(c.Count(), 2);
  EXPECT_EQ(c.SideStrandCount, 1);
  EXPECT_GE(std::max(c.Lengths[0], c.Lengths[1]), 69.0 - 1e-9);
  EXPECT_NEAR(std::min(c.Lengths[0], c.Lengths[1]), 20.0, 1e-9); // the ridge on row 30
  // Longer than MaximumSideStrandLength, the strand stays.
  settings.MaximumSideStrandLength = 10;
  EXPECT_EQ(tessera::TraceRidgeContours(minor, major, w, h, settings).Count(), 3);
  settings.SideStrandDistance = -1;
  EXPECT_THROW(tessera::TraceRidgeContours(minor, major, w, h, settings), tessera::InputError);
  settings.SideStrandDistance = 5;
  settings.MaximumSideStrandLength = std::nan("");
  EXPECT_THROW(tessera::TraceRidgeContours(minor, major, w, h, settings), tessera::InputError);
}

TEST(RidgeContours, ASideStrandLiesWithinTheDistanceAtEveryPixel)
{
  // A separate short ridge 3 pixels beside a long one (no pixel joins them): within a distance of
  // 3 at every pixel it goes (the distance is inclusive); at 2.9, or with its end pixel 4 away,
  // it stays. A huge distance is no overflow. (Every pixel major: the masks are one.)
  const int w = 80;
  const int h = 40;
  Mask minor(w * h, 0);
  Draw(minor, w, 5, 10, 74, 10);
  Draw(minor, w, 20, 13, 40, 13);
  tessera::RidgeContourSettings settings;
  settings.MinimumLength = 10;
  settings.MaximumSideStrandLength = 30;
  const auto count = [&](const Mask& m, double distance)
  {
    settings.SideStrandDistance = distance;
    return tessera::TraceRidgeContours(m, m, w, h, settings).Count();
  };
  EXPECT_EQ(count(minor, 3.0), 1);
  EXPECT_EQ(count(minor, 2.9), 2);
  Mask bent = minor;
  bent[std::size_t(13 * w + 40)] = 0;
  bent[std::size_t(14 * w + 40)] = 1; // (the end pixel a diagonal step out: 4 rows from row 10)
  EXPECT_EQ(count(bent, 3.0), 2);
  EXPECT_EQ(count(minor, 1e300), 1);
}

} // namespace
