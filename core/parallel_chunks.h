#pragma once
// Internal: contiguous chunks of a loop on the machine's cores. Each chunk writes its own output
// and the caller joins them in chunk order, so results do not depend on the number of threads;
// small inputs stay on the calling thread. The chunks run on a few threads kept for the purpose
// (parallel_chunks.cpp): starting a thread costs some 30-40 us here, and a 10^4-point filter run
// of 5 ms made eight such starts.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace tessera
{
namespace parallel
{

/// The hardware's threads, asked once: std::thread::hardware_concurrency() reads a file of /sys
/// at each call (three system calls; perf put them at some 3% of the calling thread's time in a
/// 10^4-point filter run, though no change in wall time could be measured).
inline unsigned HardwareThreads()
{
  static const unsigned count = std::max(1U, std::thread::hardware_concurrency());
  return count;
}

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
  return std::min(std::size_t(8), std::size_t(HardwareThreads()));
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

/// Runs job(context, k) for k in 1 .. chunks-1 on the kept threads and job(context, 0) on the
/// calling thread, which then also runs the chunks that no kept thread has started yet (chunks
/// must not wait for each other), and returns once all have returned (job must not throw). Returns
/// false, having run nothing, when the kept threads are busy with another caller's chunks (a pass
/// started from inside a chunk, or from another thread) or cannot be started.
bool RunOnKeptThreads(std::size_t chunks,
  void (*job)(const void* context, std::size_t k),
  const void* context);

/// guarded(1 .. chunks-1) on threads started for the call (here when none can be had), then
/// guarded(0) here; returns once all have returned.
template<class Guarded>
void RunOnNewThreads(std::size_t chunks, const Guarded& guarded)
{
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
}

/// Runs task(0 .. chunks-1), chunk 0 on the calling thread, the others on other threads (the kept
/// ones, else threads started for this call) or, when no kept thread has started one by the time
/// chunk 0 is done, on the calling thread too; chunks must not wait for each other. Rethrows the
/// first exception a task threw once all have finished.
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
  using Guarded = decltype(guarded);
  const auto job = [](const void* context, std::size_t k)
  { (*static_cast<const Guarded*>(context))(k); };
  if (!RunOnKeptThreads(chunks, job, &guarded))
  {
    RunOnNewThreads(chunks, guarded);
  }
  for (const std::exception_ptr& error : errors)
  {
    if (error)
    {
      std::rethrow_exception(error);
    }
  }
}

/// Runs item(i, chunk) for every i in [0, count) in `chunks` chunks (RunChunks), each chunk taking
/// the next item not yet taken, in turn: a few heavy items then do not hold up one chunk while the
/// others idle (a tile's display pieces under a detailed outline can cost a thousand times its
/// neighbour's). An item must write only its own results, since which chunk runs it varies from
/// run to run (chunk: for the chunk's own scratch). Once all have run, rethrows the exception of
/// the first item in order that threw, whichever chunk ran it: the same error on any number of
/// threads.
template<class Item>
void RunClaimed(std::size_t count, std::size_t chunks, const Item& item)
{
  std::atomic<std::size_t> next{ 0 };
  std::mutex lock;
  std::size_t failed = count; // the first item that threw (count: none)
  std::exception_ptr error;
  RunChunks(chunks,
    [&](std::size_t chunk)
    {
      for (std::size_t i = next++; i < count; i = next++)
      {
        try
        {
          item(i, chunk);
        }
        catch (...)
        {
          const std::lock_guard<std::mutex> guard(lock);
          if (i < failed)
          {
            failed = i;
            error = std::current_exception();
          }
        }
      }
    });
  if (error)
  {
    std::rethrow_exception(error);
  }
}

/// Runs first() on the calling thread and second() beside it (on another thread, or after first()
/// when no thread has taken it by then) when beside is true, one after the other otherwise, with
/// RunChunks' guarantees (both joined, the first exception rethrown). first() may call what must
/// stay on the calling thread (VTK).
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
