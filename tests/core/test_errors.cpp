// NumberText, the numbers in error messages and projection records: exact (reads back as the
// same double, checked on random bit patterns) and short (what a person typed comes back).
#include "errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>

namespace
{

double FromBits(std::uint64_t bits)
{
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

TEST(NumberText, ReadsBackAsTheSameDouble)
{
  std::mt19937_64 rng(3);
  int checked = 0;
  for (int k = 0; k < 200000; ++k)
  {
    // Every exponent, subnormals included; NaN and infinity bit patterns are skipped here.
    const double value = FromBits(rng());
    if (!std::isfinite(value))
    {
      continue;
    }
    const std::string text = tessera::NumberText(value);
    ASSERT_EQ(std::strtod(text.c_str(), nullptr), value) << text;
    ++checked;
  }
  EXPECT_GT(checked, 190000);
  EXPECT_EQ(tessera::NumberText(std::nextafter(0.1, 1.0)), "0.10000000000000002");
  // Powers of two (the gap below is half the gap above: correct rounding to the shortest
  // text's digit count may not read back) and their neighbours, at every exponent.
  for (int e = -1074; e <= 1023; ++e)
  {
    for (const double value : { std::ldexp(1.0, e),
           std::nextafter(std::ldexp(1.0, e), 0.0),
           std::nextafter(std::ldexp(1.0, e), HUGE_VAL) })
    {
      const std::string text = tessera::NumberText(value);
      ASSERT_EQ(std::strtod(text.c_str(), nullptr), value) << text;
    }
  }
}

TEST(NumberText, GivesBackWhatWasTyped)
{
  for (const char* typed : { "39.2",
         "1020.0000001",
         "0.1",
         "-1e-09",
         "1e+306",
         "0",
         "-0",
         "12",
         "123456789012345",
         "0.30000000000000004",
         "nan",
         "inf",
         "-inf" })
  {
    EXPECT_EQ(tessera::NumberText(std::strtod(typed, nullptr)), typed);
  }
}

} // namespace

TEST(CheckPositiveScale, RefusesScalesWhoseSquareUnderflows)
{
  using tessera::SmallestScale;
  // At the smallest scale taken, a Gaussian's 2 s^2 and an inverse multiquadric's s^2 are normal
  // doubles: the field and the curves divide by a nonzero number.
  EXPECT_GE(SmallestScale * SmallestScale, std::numeric_limits<double>::min());
  EXPECT_NO_THROW(tessera::CheckPositiveScale(SmallestScale, "basis width"));
  EXPECT_NO_THROW(tessera::CheckPositiveScale(1e300, "basis width"));
  const auto messageOf = [](double value)
  {
    try
    {
      tessera::CheckPositiveScale(value, "curve sigma");
    }
    catch (const tessera::InputError& error)
    {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(
    messageOf(std::nextafter(SmallestScale, 0.0)).find("is below 1e-150"), std::string::npos);
  EXPECT_EQ(messageOf(1e-170).rfind("curve sigma 1e-170 is below 1e-150", 0), 0u)
    << messageOf(1e-170);
  for (const double bad : { 0.0, -1.0, std::nan(""), HUGE_VAL, -HUGE_VAL })
  {
    EXPECT_NE(messageOf(bad).find("is not a positive number"), std::string::npos) << bad;
  }
}
