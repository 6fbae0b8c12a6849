// RunChunks on the kept threads: every chunk runs exactly once per pass, passes may nest or come
// from several application threads at once, and the first exception comes back to the caller.
#include "parallel_chunks.h"

#include <gtest/gtest.h>

#include <atomic>
#include <numeric>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

using tessera::parallel::RunChunks;

namespace
{

/// Runs `passes` passes of 2 .. 6 chunks; each chunk counts its own runs and notes its thread.
void CheckPasses(int passes, std::set<std::thread::id>* threads)
{
  for (int pass = 0; pass < passes; ++pass)
  {
    const std::size_t chunks = 2 + std::size_t(pass % 5);
    std::vector<std::atomic<int>> runs(chunks);
    std::vector<std::thread::id> ran(chunks);
    RunChunks(chunks,
      [&](std::size_t k)
      {
        ++runs[k];
        ran[k] = std::this_thread::get_id();
      });
    for (std::size_t k = 0; k < chunks; ++k)
    {
      ASSERT_EQ(runs[k].load(), 1) << "pass " << pass << " chunk " << k;
    }
    EXPECT_EQ(ran[0], std::this_thread::get_id()) << "chunk 0 runs on the caller";
    if (threads)
    {
      threads->insert(ran.begin() + 1, ran.end());
    }
  }
}

} // namespace

TEST(ParallelChunks, EveryChunkOncePerPassOnKeptThreads)
{
  std::set<std::thread::id> threads;
  CheckPasses(500, &threads);
  // 500 passes of up to 6 chunks: the other chunks ran on at most 5 threads (kept) and the
  // caller (which takes the chunks no kept thread has started), not on a new thread each (about
  // 1500).
  EXPECT_LE(threads.size(), 5u + threads.count(std::this_thread::get_id()));
}

TEST(ParallelChunks, NestedPassesRunOnThreadsOfTheirOwn)
{
  std::atomic<long> sum{ 0 };
  for (int pass = 0; pass < 50; ++pass)
  {
    RunChunks(3,
      [&](std::size_t k)
      {
        // A pass inside a chunk: the kept threads are busy with the outer one.
        RunChunks(2, [&](std::size_t j) { sum += long(10 * k + j); });
      });
  }
  // Per outer pass: chunks k = 0, 1, 2, each adding 10k + 0 and 10k + 1.
  EXPECT_EQ(sum.load(), 50L * (1 + 21 + 41));
}

TEST(ParallelChunks, SeveralApplicationThreadsAtOnce)
{
  std::vector<std::thread> callers;
  std::atomic<int> failures{ 0 };
  for (int c = 0; c < 3; ++c)
  {
    callers.emplace_back(
      [&]()
      {
        for (int pass = 0; pass < 200; ++pass)
        {
          std::vector<int> out(4, 0);
          RunChunks(4, [&](std::size_t k) { out[k] = int(k) + pass; });
          if (std::accumulate(out.begin(), out.end(), 0) != 6 + 4 * pass)
          {
            ++failures;
          }
        }
      });
  }
  for (std::thread& caller : callers)
  {
    caller.join();
  }
  EXPECT_EQ(failures.load(), 0);
}

TEST(ParallelChunks, FirstExceptionReachesTheCallerAndThreadsStayUsable)
{
  for (std::size_t thrower = 0; thrower < 3; ++thrower)
  {
    std::atomic<int> ran{ 0 };
    try
    {
      RunChunks(3,
        [&](std::size_t k)
        {
          ++ran;
          if (k == thrower)
          {
            throw std::runtime_error("chunk " + std::to_string(k));
          }
        });
      ADD_FAILURE() << "no exception from chunk " << thrower;
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_EQ(std::string(e.what()), "chunk " + std::to_string(thrower));
    }
    EXPECT_EQ(ran.load(), 3) << "every chunk ran (and was waited for)";
  }
  CheckPasses(20, nullptr);
}

// RunClaimed: every item once, whichever chunk takes it; the error rethrown is that of the first
// item in order that threw, on any number of chunks and however they took the items.
TEST(ParallelChunks, ClaimedItemsRunOnceAndTheFirstFailingItemsErrorIsRethrown)
{
  for (const std::size_t chunks : { 1u, 2u, 3u })
  {
    std::vector<std::atomic<int>> runs(1000);
    tessera::parallel::RunClaimed(
      runs.size(), chunks, [&](std::size_t i, std::size_t) { ++runs[i]; });
    for (std::size_t i = 0; i < runs.size(); ++i)
    {
      ASSERT_EQ(runs[i].load(), 1) << "item " << i << ", " << chunks << " chunks";
    }
    for (int round = 0; round < 20; ++round)
    {
      try
      {
        tessera::parallel::RunClaimed(1000,
          chunks,
          [](std::size_t i, std::size_t)
          {
            if (i == 617 || i == 410 || i == 999)
            {
              throw std::runtime_error("item " + std::to_string(i));
            }
          });
        ADD_FAILURE() << "no exception, " << chunks << " chunks";
      }
      catch (const std::runtime_error& e)
      {
        EXPECT_EQ(std::string(e.what()), "item 410") << chunks << " chunks";
      }
    }
  }
  CheckPasses(20, nullptr);
}
