#include "engine/vk/frame_ring.h"

#include "engine/vk/submit_faults.h"
#include "engine/vk/vk_check.h"
#include "engine/vk/vk_create.h"

namespace globe::vk {

FrameRing::FrameRing(Device& device) : device_(device) {
  VkDevice dev = device.device();
  for (auto& s : slots_) {
    s.pool = createCommandPool(dev, device.queueFamily(), VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
    s.cmd = allocateCommandBuffer(dev, s.pool);
    s.done = createFence(dev, /*signalled=*/true);  // the first begin() must not wait
    s.imageAcquired = createSemaphore(dev);
  }
}

FrameRing::Slot FrameRing::begin(uint64_t frame) {
  Resources& s = at(frame);
  VkFence fence = s.done;
  GLOBE_VK_CHECK(vkWaitForFences(device_.device(), 1, &fence, VK_TRUE, UINT64_MAX));
  // The fence is reset only in submit(): a frame abandoned before submission (out-of-date
  // swapchain) must leave it signalled, or the next wait would never return.
  GLOBE_VK_CHECK(vkResetCommandPool(device_.device(), s.pool, 0));
  return {s.cmd, s.imageAcquired};
}

void FrameRing::submit(uint64_t frame, VkSemaphore renderFinished) {
  Resources& s = at(frame);
  VkFence fence = s.done;
  GLOBE_VK_CHECK(vkResetFences(device_.device(), 1, &fence));
  VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  wait.semaphore = s.imageAcquired;
  wait.stageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signal.semaphore = renderFinished;
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo cmd{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmd.commandBuffer = s.cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.waitSemaphoreInfoCount = 1;
  submit.pWaitSemaphoreInfos = &wait;
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmd;
  submit.signalSemaphoreInfoCount = 1;
  submit.pSignalSemaphoreInfos = &signal;
  GLOBE_VK_SUBMIT(SubmitSite::kFrame, vkQueueSubmit2(device_.queue(), 1, &submit, fence));
}

}  // namespace globe::vk
