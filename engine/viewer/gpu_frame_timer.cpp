#include "engine/viewer/gpu_frame_timer.h"

namespace globe {

GpuFrameTimer::GpuFrameTimer(vk::Device& device)
    : device_(device),
      supported_(device.properties().limits.timestampComputeAndGraphics == VK_TRUE),
      period_ns_(double(device.properties().limits.timestampPeriod)) {
  if (supported_) pool_ = vk::createTimestampQueryPool(device.device(), 2 * vk::kFramesInFlight);
}

double GpuFrameTimer::takeMs(uint32_t slot) {
  if (!supported_ || !written_[slot]) return 0.0;
  written_[slot] = false;
  uint64_t t[2] = {0, 0};
  if (vkGetQueryPoolResults(device_.device(), pool_, 2 * slot, 2, sizeof t, t, sizeof(uint64_t),
                            VK_QUERY_RESULT_64_BIT) != VK_SUCCESS)
    return 0.0;
  return t[1] >= t[0] ? double(t[1] - t[0]) * period_ns_ * 1e-6 : 0.0;
}

void GpuFrameTimer::begin(VkCommandBuffer cmd, uint32_t slot) {
  if (!supported_) return;
  vkCmdResetQueryPool(cmd, pool_, 2 * slot, 2);
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, pool_, 2 * slot);
}

void GpuFrameTimer::end(VkCommandBuffer cmd, uint32_t slot) {
  if (!supported_) return;
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, pool_, 2 * slot + 1);
  written_[slot] = true;
}

}  // namespace globe
