#include "planet/core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
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
