#pragma once
// What the payload pool did in one frame; the benchmark replay records these per frame.
#include <cstdint>

namespace globe {

struct StreamingStats {
  uint32_t dispatched = 0;     // generations started this frame (<= dispatch budget)
  uint32_t inFlight = 0;       // generations started and not yet finished, after this frame's dispatch
  uint32_t completed = 0;      // generations that finished this frame
  uint32_t evicted = 0;        // payloads evicted this frame
  uint32_t requested = 0;      // distinct nodes asked for this frame
  uint32_t queueLength = 0;    // requests left waiting after this frame's dispatch
  uint32_t residentNodes = 0;  // payloads ready to draw
  double residentMiB = 0.0;    // device memory held by resident and in-flight payloads
  uint32_t starvedByPool = 0;  // requests skipped because no slot could be freed (pool exhausted)
  uint32_t failed = 0;         // generations that came back failed this frame (nodes asked for again)
  // Look-ahead (RequestPriority::kPrefetch); also included in the totals above.
  uint32_t prefetchRequested = 0;   // distinct nodes asked for only as prefetch this frame
  uint32_t prefetchDispatched = 0;  // prefetch generations started this frame
};

}  // namespace globe
