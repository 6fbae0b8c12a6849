#pragma once
// The consumers' failure: each check is `if (!(condition)) return Failed(...)` in main, which
// prints "FAILED: " and the formatted message and makes the program exit with status 1
// (run_install_test.cmake then fails the ctest, which also requires the program to print exactly
// "ok"). Written out at each check, so that it holds in every build type, unlike assert().
#include <cstdarg>
#include <cstdio>

inline int Failed(const char* format, ...)
{
  std::va_list arguments;
  va_start(arguments, format);
  std::printf("FAILED: ");
  std::vprintf(format, arguments);
  std::printf("\n");
  va_end(arguments);
  return 1;
}
