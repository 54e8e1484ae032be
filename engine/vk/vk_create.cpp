#include "engine/vk/vk_create.h"

#include "engine/vk/vk_check.h"

namespace globe::vk {

UniqueFence createFence(VkDevice device, bool signalled) {
  VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  if (signalled) info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  VkFence fence;
  GLOBE_VK_CHECK(vkCreateFence(device, &info, nullptr, &fence));
  return UniqueFence(device, fence);
}

UniqueSemaphore createSemaphore(VkDevice device) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore semaphore;
  GLOBE_VK_CHECK(vkCreateSemaphore(device, &info, nullptr, &semaphore));
  return UniqueSemaphore(device, semaphore);
}

UniqueCommandPool createCommandPool(VkDevice device, uint32_t queueFamily, VkCommandPoolCreateFlags flags) {
  VkCommandPoolCreateInfo info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  info.flags = flags;
  info.queueFamilyIndex = queueFamily;
  VkCommandPool pool;
  GLOBE_VK_CHECK(vkCreateCommandPool(device, &info, nullptr, &pool));
  return UniqueCommandPool(device, pool);
}

VkCommandBuffer allocateCommandBuffer(VkDevice device, VkCommandPool pool) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd;
  GLOBE_VK_CHECK(vkAllocateCommandBuffers(device, &alloc, &cmd));
  return cmd;
}

UniqueQueryPool createTimestampQueryPool(VkDevice device, uint32_t count) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = count;
  VkQueryPool pool;
  GLOBE_VK_CHECK(vkCreateQueryPool(device, &info, nullptr, &pool));
  return UniqueQueryPool(device, pool);
}

UniqueImageView createImageView2D(VkDevice device, VkImage image, VkFormat format, VkImageAspectFlags aspect) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image;
  info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  info.format = format;
  info.subresourceRange = {aspect, 0, 1, 0, 1};
  VkImageView view;
  GLOBE_VK_CHECK(vkCreateImageView(device, &info, nullptr, &view));
  return UniqueImageView(device, view);
}

}  // namespace globe::vk
