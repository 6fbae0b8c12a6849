// The threads that RunChunks keeps between passes (parallel_chunks.h). A pass hands its chunks
// 1 .. n-1 to them and runs chunk 0 itself, then any of the others that no kept thread has
// taken yet. Between passes they poll briefly, then sleep on a
// condition variable. They are started on first use, as many as the largest pass has needed, and
// stopped and joined at exit.
//
// One pass at a time: a pass started while another holds them (from inside a chunk, or from a
// second thread of the application) is told no and starts threads of its own, as before, so
// nesting cannot deadlock. A child process made by fork() has none of its parent's threads: it
// never uses them (its passes start their own), and leaves them unjoined at exit.
#include "parallel_chunks.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include <unistd.h>

namespace tessera
{
namespace parallel
{
namespace
{

using Job = void (*)(const void*, std::size_t);
using Clock = std::chrono::steady_clock;

/// Set once the kept threads are gone (static destruction): later passes start their own.
std::atomic<bool> KeptThreadsGone{ false };

/// How long a kept thread, or a pass's caller, polls before it sleeps. Waking a thread that
/// sleeps on another core costs some 50 us on this VM (about as much as starting one), and the
/// passes of one filter run come a fraction of a millisecond apart: polling that long is cheap.
constexpr auto PollTime = std::chrono::microseconds(1000);

/// Polls done() until it holds or PollTime has passed; true if it holds.
template<class Done>
bool PollFor(const Done& done)
{
  const Clock::time_point until = Clock::now() + PollTime;
  for (;;)
  {
    for (int k = 0; k < 64; ++k)
    {
      if (done())
      {
        return true;
      }
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    }
    // A thread waiting to run on this core (the pass's caller, another program) goes first: a
    // poll must not take the core from the work it waits for.
    std::this_thread::yield();
    if (Clock::now() >= until)
    {
      return done();
    }
  }
}

class KeptThreads
{
public:
  KeptThreads() = default;
  KeptThreads(const KeptThreads&) = delete;
  KeptThreads& operator=(const KeptThreads&) = delete;

  ~KeptThreads()
  {
    {
      std::lock_guard<std::mutex> lock(this->Lock);
      this->Stop = true;
      ++this->Passes; // ends the polls
    }
    this->Wake.notify_all();
    for (std::thread& thread : this->Threads)
    {
      thread.join();
    }
  }

  /// False in a child process made by fork(), which has none of the threads.
  bool InOwnProcess() const { return this->Owner == ::getpid(); }

  bool Run(std::size_t chunks, Job job, const void* context)
  {
    if (!this->InOwnProcess())
    {
      return false;
    }
    {
      std::lock_guard<std::mutex> lock(this->Lock);
      if (this->Busy || this->Stop || !this->Grow(chunks - 1))
      {
        return false;
      }
      this->Busy = true;
      this->CurrentJob = job;
      this->Context = context;
      this->NextChunk = 1;
      this->EndChunk = chunks;
      this->Unfinished = chunks - 1;
      ++this->Passes;
    }
    this->Wake.notify_all();
    job(context, 0);
    this->RunUnclaimedChunks(job, context);
    if (!(this->Polling && PollFor([this]() { return this->Unfinished == 0; })))
    {
      std::unique_lock<std::mutex> lock(this->Lock);
      this->Finished.wait(lock, [this]() { return this->Unfinished == 0; });
    }
    std::lock_guard<std::mutex> lock(this->Lock);
    this->Busy = false;
    this->CurrentJob = nullptr;
    this->Context = nullptr;
    return true;
  }

private:
  /// The caller, its chunk 0 done, runs the chunks no kept thread has taken yet. A kept thread
  /// can be slow to start one: asleep (some 50 us to wake), or off its core when another program
  /// keeps that core busy, for a scheduler slice of milliseconds. Waiting for it made a pass of
  /// 0.1 ms take several, and the filters four times slower on a machine with one core in use.
  void RunUnclaimedChunks(Job job, const void* context)
  {
    std::unique_lock<std::mutex> lock(this->Lock);
    while (this->NextChunk < this->EndChunk)
    {
      const std::size_t k = this->NextChunk++;
      lock.unlock();
      job(context, k);
      lock.lock();
      --this->Unfinished;
    }
  }

  /// At least count threads (the lock held); false when the system gives no more.
  bool Grow(std::size_t count)
  {
    while (this->Threads.size() < count)
    {
      try
      {
        const std::uint64_t seen = this->Passes;
        this->Threads.emplace_back([this, seen]() { this->Work(seen); });
      }
      catch (const std::system_error&)
      {
        return false;
      }
      // More threads than cores (TESSERA_THREADS above them): a thread that polls would keep
      // one that has a chunk to run off its core, so all sleep at once.
      this->Polling = this->Threads.size() < HardwareThreads();
    }
    return true;
  }

  /// A kept thread: takes chunks while a pass has some left; else polls for the next pass for a
  /// while, then sleeps. A chunk handed out is always run, even when stopping, so that its pass
  /// can finish. seen: the last pass it has looked at.
  void Work(std::uint64_t seen)
  {
    for (;;)
    {
      if (this->Polling)
      {
        PollFor([this, seen]() { return this->Passes != seen; });
      }
      std::unique_lock<std::mutex> lock(this->Lock);
      this->Wake.wait(lock, [this]() { return this->Stop || this->NextChunk < this->EndChunk; });
      if (this->NextChunk >= this->EndChunk)
      {
        return; // stopping, nothing left to run
      }
      seen = this->Passes;
      const std::size_t k = this->NextChunk++;
      const Job job = this->CurrentJob;
      const void* const context = this->Context;
      lock.unlock();
      job(context, k);
      lock.lock();
      if (--this->Unfinished == 0)
      {
        this->Finished.notify_one();
      }
    }
  }

  const pid_t Owner = ::getpid();
  std::mutex Lock;
  std::condition_variable Wake;     // the kept threads: a chunk to take, or stop
  std::condition_variable Finished; // the pass's caller: its last chunk returned
  std::vector<std::thread> Threads;
  // Written under the lock; the atomics are also polled without it.
  std::atomic<std::uint64_t> Passes{ 0 };   // passes started (and one more to stop)
  std::atomic<std::size_t> Unfinished{ 0 }; // the pass's chunks not yet returned (not 0)
  Job CurrentJob = nullptr;
  const void* Context = nullptr;
  std::size_t NextChunk = 0;          // the next chunk to hand out ...
  std::size_t EndChunk = 0;           // ... up to this one
  std::atomic<bool> Polling{ false }; // the threads and the caller poll between passes
  bool Busy = false;                  // a pass holds the threads
  bool Stop = false;
};

/// Owns the kept threads, and stops them at exit. In a forked child it leaves them alone: their
/// handles, mutex and condition variables are the parent's (destroying a condition variable that
/// a parent's thread waited on blocks for ever), so the child's copy is never destroyed.
struct KeptThreadsOwner
{
  KeptThreads* Threads = new KeptThreads;
  ~KeptThreadsOwner()
  {
    KeptThreadsGone = true;
    if (this->Threads->InOwnProcess())
    {
      delete this->Threads;
    }
  }
};

} // namespace

bool RunOnKeptThreads(std::size_t chunks,
  void (*job)(const void* context, std::size_t k),
  const void* context)
{
  if (chunks <= 1 || KeptThreadsGone)
  {
    return false;
  }
  static KeptThreadsOwner owner;
  return owner.Threads->Run(chunks, job, context);
}

} // namespace parallel
} // namespace tessera
