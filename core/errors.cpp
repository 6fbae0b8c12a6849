#include "errors.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace tessera
{

// Locale-free (snprintf would follow LC_NUMERIC, which a GUI may set to ","). The shortest
// scientific text that reads back (std::to_chars) gives the digits needed; printed %g-style with
// at least 15 of them, so that 500000 stays "500000" (the shortest text would be "5e+05") while
// trailing zeros still go. Correct rounding to that many digits does not always read back where
// the shortest text did (2^-509: the gap below a power of two is half the gap above): one more
// digit then, up to 17, which always do.
std::string NumberText(double value)
{
  char buffer[40];
  const char* const begin = buffer;
  const std::to_chars_result shortest =
    std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
  const char* const exponent = std::find(begin, static_cast<const char*>(shortest.ptr), 'e');
  if (exponent == shortest.ptr)
  {
    return std::string(buffer, shortest.ptr); // nan, inf
  }
  const int digits =
    int(std::count_if(begin, exponent, [](char c) { return c >= '0' && c <= '9'; }));
  for (int precision = std::max(digits, 15);; ++precision)
  {
    const std::to_chars_result end =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, precision);
    double back = 0.0;
    std::from_chars(buffer, end.ptr, back);
    if (back == value || precision >= 17)
    {
      return std::string(buffer, end.ptr);
    }
  }
}

void CheckPositiveScale(double value, const std::string& what)
{
  if (!(value > 0.0) || !std::isfinite(value))
  {
    throw InputError(what + " " + NumberText(value) + " is not a positive number");
  }
  if (value < SmallestScale)
  {
    throw InputError(what + " " + NumberText(value) + " is below " + NumberText(SmallestScale) +
      ", where its square underflows to zero (the Gaussian or radial basis would divide 0 by 0)");
  }
}

std::string DuplicatePairNames(const std::vector<std::pair<std::int32_t, std::int32_t>>& pairs)
{
  return ListNames(pairs.size(),
    [&](std::size_t k)
    {
      return "point " + std::to_string(pairs[k].first) + " (of point " +
        std::to_string(pairs[k].second) + ")";
    });
}

} // namespace tessera
