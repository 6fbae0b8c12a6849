#pragma once
// Internal: contiguous chunks of a loop on the machine's cores (std::thread). Each chunk writes
// its own output and the caller joins them in chunk order, so results do not depend on the number
// of threads; small inputs stay on the calling thread.

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace tessera
{
namespace parallel
{

/// The most threads a pass may use: the environment variable TESSERA_THREADS when it holds a
/// number from 1 to 64 (read at each call: a few calls per operation), else the hardware's, at
/// most 8. TESSERA_THREADS=1 runs everything on the calling thread; the tests set it to force
/// several chunks on any machine.
inline std::size_t ThreadLimit()
{
  if (const char* text = std::getenv("TESSERA_THREADS"))
  {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end != text && *end == '\0' && value >= 1 && value <= 64)
    {
      return std::size_t(value);
    }
  }
  return std::min(std::size_t(8), std::size_t(std::max(1U, std::thread::hardware_concurrency())));
}

/// Threads for a pass over `work` items: up to ThreadLimit(), with at least minimumPerThread items
/// each (below that, starting a thread costs more than it saves: small inputs run serially).
inline std::size_t ThreadCount(std::int64_t work, std::int64_t minimumPerThread = 25000)
{
  const std::size_t useful = std::size_t(std::max<std::int64_t>(1, work / minimumPerThread));
  return std::min(ThreadLimit(), useful);
}

/// The chunks + 1 boundaries of `chunks` contiguous, nearly equal parts of [0, n).
inline std::vector<std::int32_t> ChunkBounds(std::int32_t n, std::size_t chunks)
{
  std::vector<std::int32_t> bounds(chunks + 1);
  for (std::size_t k = 0; k <= chunks; ++k)
  {
    bounds[k] = std::int32_t(std::int64_t(n) * std::int64_t(k) / std::int64_t(chunks));
  }
  return bounds;
}

/// Runs task(0 .. chunks-1), chunk 0 on the calling thread, the others on their own threads;
/// rethrows the first exception a task threw once all have finished.
template<class Task>
void RunChunks(std::size_t chunks, const Task& task)
{
  if (chunks <= 1)
  {
    task(0);
    return;
  }
  std::vector<std::exception_ptr> errors(chunks);
  const auto guarded = [&](std::size_t k)
  {
    try
    {
      task(k);
    }
    catch (...)
    {
      errors[k] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  threads.reserve(chunks - 1);
  for (std::size_t k = 1; k < chunks; ++k)
  {
    try
    {
      threads.emplace_back(guarded, k);
    }
    catch (const std::system_error&)
    {
      guarded(k); // no thread to be had: run it here
    }
  }
  guarded(0);
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  for (const std::exception_ptr& error : errors)
  {
    if (error)
    {
      std::rethrow_exception(error);
    }
  }
}

/// Runs first() on the calling thread and second() beside it on a thread of its own when beside
/// is true, one after the other otherwise, with RunChunks' guarantees (both joined, the first
/// exception rethrown). first() may call what must stay on the calling thread (VTK).
template<class First, class Second>
void RunSideBySide(bool beside, const First& first, const Second& second)
{
  if (!beside)
  {
    first();
    second();
    return;
  }
  RunChunks(2,
    [&](std::size_t k)
    {
      if (k == 0)
      {
        first();
      }
      else
      {
        second();
      }
    });
}

} // namespace parallel
} // namespace tessera
