#pragma once
// The one way to create the small Vulkan objects every part needs (fences, semaphores, command
// pools and buffers, timestamp query pools, 2D image views): each returns an owner and throws
// VulkanError (vk_check.h) on failure, like every other engine/vk constructor.
#include "engine/vk/vk_handles.h"

namespace globe::vk {

// `signalled`: created signalled, so the first wait on it returns at once.
UniqueFence createFence(VkDevice device, bool signalled = false);
UniqueSemaphore createSemaphore(VkDevice device);
UniqueCommandPool createCommandPool(VkDevice device, uint32_t queueFamily, VkCommandPoolCreateFlags flags);
// One primary command buffer from `pool` (freed with the pool).
VkCommandBuffer allocateCommandBuffer(VkDevice device, VkCommandPool pool);
// `count` timestamp queries, not yet reset.
UniqueQueryPool createTimestampQueryPool(VkDevice device, uint32_t count);
// A view of mip 0, layer 0 of a 2D image.
UniqueImageView createImageView2D(VkDevice device, VkImage image, VkFormat format, VkImageAspectFlags aspect);

}  // namespace globe::vk
