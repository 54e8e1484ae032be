#pragma once
// The one thread loop: splits [0, count) into chunks handed out to a few threads. Every CPU-parallel
// loop in globe (elevation export, surface-ray truth) runs through it.
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace globe {

// Called on the calling thread with the fraction done, [0, 1]; may be empty.
using ProgressFn = std::function<void(double fraction)>;

// Runs body(begin, end) over [0, count) in chunks of `chunk` items on `threads` threads (the caller
// is one of them; 0 counts as 1) and reports progress between chunks. body must be safe to run
// concurrently on disjoint ranges. If a body throws, no further chunks start, every thread is
// joined, and the first exception is rethrown on the calling thread.
void parallelFor(std::size_t count, std::size_t chunk, unsigned threads,
                 const std::function<void(std::size_t begin, std::size_t end)>& body, const ProgressFn& progress = {});

// The same loop on threads that persist between calls, for loops that run every few milliseconds
// (a physics step): parallelFor starts and joins its helpers on each call, ~0.1 ms and a wait for
// the scheduler every time (1.5 ms on average for a 2-thread physics step on a busy machine).
// run() has parallelFor's contract (no progress); one run() at a time.
class ThreadTeam {
 public:
  explicit ThreadTeam(unsigned threads);  // the caller is one of them; 0 counts as 1
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  void run(std::size_t count, std::size_t chunk, const std::function<void(std::size_t begin, std::size_t end)>& body);
  unsigned threads() const { return unsigned(helpers_.size()) + 1; }

 private:
  void helperLoop();
  void work();

  std::mutex mutex_;
  std::condition_variable wake_, idle_;
  uint64_t generation_ = 0;  // runs started
  unsigned busy_ = 0;        // helpers inside the current run
  bool stop_ = false;
  // The current run (written under the lock before the helpers wake).
  const std::function<void(std::size_t, std::size_t)>* body_ = nullptr;
  std::size_t count_ = 0, chunk_ = 1, chunks_ = 0;
  std::size_t next_ = 0;  // next chunk, under the lock
  std::exception_ptr failure_;
  std::vector<std::thread> helpers_;  // last: start after every member they read
};

}  // namespace globe
