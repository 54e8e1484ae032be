#pragma once
// GPU time of each viewer frame (its command buffer: generation, terrain, sky, water), from two
// timestamps per frame-in-flight slot, read back after FrameRing::begin has waited for the slot's
// fence, so reading never stalls. Zero where the device has no timestamps on graphics queues.
#include "engine/vk/device.h"
#include "engine/vk/frame_ring.h"
#include "engine/vk/vk_create.h"

#include <array>

namespace globe {

class GpuFrameTimer {
 public:
  explicit GpuFrameTimer(vk::Device& device);

  // Milliseconds of the frame last recorded in `slot` (complete: its fence was waited for), or 0.
  double takeMs(uint32_t slot);
  // Resets the slot's queries and writes the first timestamp: first thing in the frame's command buffer.
  void begin(VkCommandBuffer cmd, uint32_t slot);
  // The last timestamp, after the frame's scene work.
  void end(VkCommandBuffer cmd, uint32_t slot);

 private:
  vk::Device& device_;
  bool supported_ = false;
  double period_ns_ = 1.0;
  vk::UniqueQueryPool pool_;
  std::array<bool, vk::kFramesInFlight> written_{};
};

}  // namespace globe
