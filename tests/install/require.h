#pragma once
// The consumers' assertion: a condition that must hold, else the program prints "FAILED: " and
// the formatted message and exits with status 1 (run_install_test.cmake then fails the ctest,
// which also requires the program to print exactly "ok").
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

inline void Require(bool condition, const char* format, ...)
{
  if (condition)
  {
    return;
  }
  std::va_list arguments;
  va_start(arguments, format);
  std::printf("FAILED: ");
  std::vprintf(format, arguments);
  std::printf("\n");
  va_end(arguments);
  std::exit(1);
}
