#pragma once
// The consumers' assertion: REQUIRE(condition, format, ...) checks a condition that must hold;
// when it does not, the program prints "FAILED: ", the file and line, the condition and the
// formatted message, and exits with status 1 (run_install_test.cmake then fails the ctest, which
// also requires the program to print exactly "ok"). Active in every build type, unlike assert().
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

inline void FailRequirement(const char* file,
  int line,
  const char* condition,
  const char* format,
  ...)
{
  std::va_list arguments;
  va_start(arguments, format);
  std::printf("FAILED: %s:%d: REQUIRE(%s): ", file, line, condition);
  std::vprintf(format, arguments);
  std::printf("\n");
  va_end(arguments);
  std::exit(1);
}

#define REQUIRE(condition, ...)                                                                    \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      FailRequirement(__FILE__, __LINE__, #condition, __VA_ARGS__);                                \
    }                                                                                              \
  } while (false)
