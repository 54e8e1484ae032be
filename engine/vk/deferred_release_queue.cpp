#include "engine/vk/deferred_release_queue.h"

#include <algorithm>

namespace globe::vk {

size_t DeferredReleaseQueue::collect(uint64_t completedFrame) {
  // Entries are not necessarily sorted by frame (a caller may retire with an older frame number),
  // so partition rather than pop from the front; release order stays retirement order.
  auto done =
      std::stable_partition(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.frame > completedFrame; });
  size_t released = size_t(entries_.end() - done);
  for (auto it = done; it != entries_.end(); ++it) it->resource.reset();
  entries_.erase(done, entries_.end());
  return released;
}

void DeferredReleaseQueue::releaseAll() {
  for (auto& e : entries_) e.resource.reset();
  entries_.clear();
}

}  // namespace globe::vk
