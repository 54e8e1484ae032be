#pragma once
// The one thread loop: splits [0, count) into chunks handed out to a few threads. Every CPU-parallel
// loop in globe (elevation export, surface-ray truth) runs through it.
#include <cstddef>
#include <functional>

namespace globe {

// Called on the calling thread with the fraction done, [0, 1]; may be empty.
using ProgressFn = std::function<void(double fraction)>;

// Runs body(begin, end) over [0, count) in chunks of `chunk` items on `threads` threads (the caller
// is one of them; 0 counts as 1) and reports progress between chunks. body must be safe to run
// concurrently on disjoint ranges. If a body throws, no further chunks start, every thread is
// joined, and the first exception is rethrown on the calling thread.
void parallelFor(std::size_t count, std::size_t chunk, unsigned threads,
                 const std::function<void(std::size_t begin, std::size_t end)>& body, const ProgressFn& progress = {});

}  // namespace globe
