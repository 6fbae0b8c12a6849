#include "errors.h"

#include <cstdio>
#include <cstdlib>

namespace tessera
{

// 15 significant digits read back exactly for most values a person types; 17 always do.
std::string NumberText(double value)
{
  char buffer[40];
  for (int digits = 15; digits <= 17; ++digits)
  {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    if (digits == 17 || std::strtod(buffer, nullptr) == value)
    {
      break;
    }
  }
  return buffer;
}

} // namespace tessera
