#pragma once
// Per-frame-in-flight resources of a presenting frame loop: a command pool and buffer, a fence
// signalled when the frame's GPU work is done, and the semaphore its swapchain image arrives on.
// With two frames in flight the CPU records frame N while the GPU still runs frame N-1.
#include "engine/vk/device.h"
#include "engine/vk/vk_handles.h"

#include <array>

namespace globe::vk {

constexpr uint32_t kFramesInFlight = 2;

class FrameRing {
 public:
  struct Slot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;  // reset and ready to begin
    VkSemaphore imageAcquired = VK_NULL_HANDLE;
  };

  explicit FrameRing(Device& device);

  // Waits until frame `frame`'s slot is free (frame - kFramesInFlight has completed on the GPU)
  // and resets its command pool. Frames are numbered 0, 1, 2, ...
  Slot begin(uint64_t frame);
  // Submits the slot's command buffer: waits for the image at the transfer stage (the first
  // swapchain write is a blit), signals `renderFinished` and the slot's fence.
  void submit(uint64_t frame, VkSemaphore renderFinished);

 private:
  struct Resources {
    UniqueCommandPool pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;  // freed with the pool
    UniqueFence done;                      // created signalled: the first wait returns at once
    UniqueSemaphore imageAcquired;
  };
  Resources& at(uint64_t frame) { return slots_[frame % kFramesInFlight]; }

  Device& device_;
  std::array<Resources, kFramesInFlight> slots_;
};

}  // namespace globe::vk
