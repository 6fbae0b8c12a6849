#include "errors.h"

#include <gtest/gtest.h>

TEST(InputError, IsInvalidArgumentWithMessage)
{
  try
  {
    throw tessera::InputError("point 17 has a NaN coordinate");
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_STREQ(e.what(), "point 17 has a NaN coordinate");
    return;
  }
  FAIL() << "InputError was not caught as std::invalid_argument";
}
