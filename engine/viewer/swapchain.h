#pragma once
// The window's swapchain: images the viewer blits its frame into and presents. Recreated when
// the window changes size or the surface reports it out of date; the old swapchain's objects are
// released through the DeferredReleaseQueue once the frames that used them are done.
#include "engine/vk/deferred_release_queue.h"
#include "engine/vk/device.h"
#include "engine/vk/vk_handles.h"

#include <optional>
#include <vector>

namespace globe::vk {

class Swapchain {
 public:
  // `framebufferExtent` is the window's size in pixels; the surface may impose its own.
  // vsync: FIFO presentation (always available); otherwise MAILBOX or IMMEDIATE when offered.
  Swapchain(Device& device, VkExtent2D framebufferExtent, bool vsync);

  // Builds a new swapchain; the old one is retired until frame `lastUseFrame` completes.
  void recreate(VkExtent2D framebufferExtent, DeferredReleaseQueue& releases, uint64_t lastUseFrame);

  // Index of the next image, with `acquired` signalled once it may be written; nullopt when the
  // swapchain is out of date (recreate, then acquire again).
  std::optional<uint32_t> acquire(VkSemaphore acquired);
  // Queues `image` for presentation after renderFinished(image) is signalled. Returns false when
  // the swapchain should be recreated before the next frame.
  bool present(uint32_t image);

  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  uint32_t imageCount() const { return uint32_t(state_.images.size()); }
  uint32_t minImageCount() const { return minImageCount_; }
  VkImage image(uint32_t i) const { return state_.images[i]; }
  VkImageView view(uint32_t i) const { return state_.views[i]; }
  // Signalled by the frame that renders into image i, waited on by its presentation. One per image
  // rather than per frame in flight: presentation has no fence telling when it is safe to reuse.
  VkSemaphore renderFinished(uint32_t i) const { return state_.renderFinished[i]; }
  // Increments on every recreation, so dependants (framebuffers, targets) know to rebuild.
  uint64_t generation() const { return generation_; }

 private:
  struct State {
    UniqueSwapchain swapchain;
    std::vector<VkImage> images;  // owned by the swapchain
    std::vector<UniqueImageView> views;
    std::vector<UniqueSemaphore> renderFinished;
  };
  void create(VkExtent2D framebufferExtent, VkSwapchainKHR old);

  Device& device_;
  bool vsync_;
  State state_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkColorSpaceKHR colourSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkExtent2D extent_{};
  uint32_t minImageCount_ = 2;
  uint64_t generation_ = 0;
};

}  // namespace globe::vk
