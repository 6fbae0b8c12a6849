#pragma once
// The main of a Google Benchmark program whose --help (or -h) first says what it measures, then
// lists Google Benchmark's options (BENCHMARK_MAIN's --help gives only those).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>

inline int RunBenchmarks(int argc, char** argv, const char* description)
{
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
    {
      static char help[] = "--help"; // (Google Benchmark knows only the long form)
      argv[i] = help;
      std::printf("%s\n\n", description);
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
  {
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
