#pragma once
// Keeps GPU-visible objects alive until the frames that may still use them have completed
// (bgfx's idea): instead of waiting for the device, the owner of a buffer, image, swapchain ...
// hands it here with the number of the last frame that used it, and the frame loop calls
// collect() with the newest frame whose fence it has seen signalled.
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace globe::vk {

class DeferredReleaseQueue {
 public:
  DeferredReleaseQueue() = default;
  ~DeferredReleaseQueue() { releaseAll(); }
  DeferredReleaseQueue(const DeferredReleaseQueue&) = delete;
  DeferredReleaseQueue& operator=(const DeferredReleaseQueue&) = delete;

  // Takes ownership of `resource` (any movable RAII owner) until frame `lastUseFrame` is complete.
  template <class T>
  void retire(uint64_t lastUseFrame, T&& resource) {
    static_assert(!std::is_lvalue_reference_v<T>, "retire() takes ownership: pass std::move(resource)");
    entries_.push_back({lastUseFrame, std::make_unique<Holder<std::decay_t<T>>>(std::forward<T>(resource))});
  }

  // Destroys everything whose last use was at or before `completedFrame`, oldest first.
  // Returns how many entries were released.
  size_t collect(uint64_t completedFrame);

  // Destroys everything; only after the device is idle (shutdown, or a full wait).
  void releaseAll();

  size_t size() const { return entries_.size(); }

 private:
  struct Base {
    virtual ~Base() = default;
  };
  template <class T>
  struct Holder final : Base {
    explicit Holder(T&& v) : value(std::move(v)) {}
    T value;
  };
  struct Entry {
    uint64_t frame;
    std::unique_ptr<Base> resource;
  };
  std::vector<Entry> entries_;  // in retirement order
};

}  // namespace globe::vk
