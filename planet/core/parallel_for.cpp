#include "planet/core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace globe {

void parallelFor(std::size_t count, std::size_t chunk, unsigned threads,
                 const std::function<void(std::size_t, std::size_t)>& body, const ProgressFn& progress) {
  chunk = std::max<std::size_t>(chunk, 1);
  const std::size_t chunks = (count + chunk - 1) / chunk;
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::mutex failureMutex;
  std::exception_ptr failure;
  auto work = [&](bool report) {
    try {
      for (std::size_t c = next.fetch_add(1); c < chunks; c = next.fetch_add(1)) {
        body(c * chunk, std::min(count, (c + 1) * chunk));
        const std::size_t d = done.fetch_add(1) + 1;
        if (report && progress) progress(static_cast<double>(d) / static_cast<double>(chunks));
      }
    } catch (...) {
      // An exception escaping a std::thread would terminate the process: keep the first one.
      next = chunks;  // no new chunks; running ones finish
      std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure) failure = std::current_exception();
    }
  };
  std::vector<std::thread> helpers;
  const unsigned n =
      std::max(1U, std::min<unsigned>(threads, static_cast<unsigned>(std::min<std::size_t>(chunks, 256))));
  for (unsigned t = 1; t < n; ++t) helpers.emplace_back(work, false);
  work(true);
  for (std::thread& t : helpers) t.join();
  if (failure) std::rethrow_exception(failure);
  if (progress) progress(1.0);
}

}  // namespace globe

namespace globe {

ThreadTeam::ThreadTeam(unsigned threads) {
  for (unsigned t = 1; t < std::max(threads, 1U); ++t) helpers_.emplace_back([this] { helperLoop(); });
}

ThreadTeam::~ThreadTeam() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : helpers_) t.join();
}

// Takes chunks until none is left. Chunks are a few per run, so one lock per chunk costs nothing.
void ThreadTeam::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (next_ < chunks_) {
    const std::size_t c = next_++;
    lock.unlock();
    try {
      (*body_)(c * chunk_, std::min(count_, (c + 1) * chunk_));
    } catch (...) {
      lock.lock();
      next_ = chunks_;  // no new chunks; running ones finish
      if (!failure_) failure_ = std::current_exception();
      continue;
    }
    lock.lock();
  }
}

void ThreadTeam::helperLoop() {
  uint64_t seen = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    ++busy_;
    lock.unlock();
    work();
    lock.lock();
    if (--busy_ == 0) idle_.notify_all();
  }
}

void ThreadTeam::run(std::size_t count, std::size_t chunk, const std::function<void(std::size_t, std::size_t)>& body) {
  chunk = std::max<std::size_t>(chunk, 1);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    body_ = &body;
    count_ = count;
    chunk_ = chunk;
    chunks_ = (count + chunk - 1) / chunk;
    next_ = 0;
    failure_ = nullptr;
    ++generation_;
  }
  if (chunks_ > 1) wake_.notify_all();
  work();
  std::unique_lock<std::mutex> lock(mutex_);
  // A helper that wakes after the run is over finds no chunk left and goes back to sleep; the body
  // it would call stays valid until every helper that took a chunk is done.
  idle_.wait(lock, [&] { return busy_ == 0; });
  body_ = nullptr;
  if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

}  // namespace globe
