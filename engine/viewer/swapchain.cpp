#include "engine/viewer/swapchain.h"

#include "engine/vk/vk_check.h"
#include "engine/vk/vk_create.h"

#include <algorithm>
#include <stdexcept>

namespace globe::vk {

namespace {

// 8-bit UNORM like the scene target, whose display encoding is close to sRGB (display_encoding.h),
// so the blit is a copy; it must accept blits. A surface with only sRGB formats shows it brighter.
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  uint32_t count = 0;
  GLOBE_VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  GLOBE_VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()));
  auto blittable = [&](VkFormat f) {
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(physical, f, &props);
    return (props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT) != 0;
  };
  for (VkFormat preferred :
       {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB}) {
    for (const auto& f : formats)
      if (f.format == preferred && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR && blittable(f.format)) return f;
  }
  for (const auto& f : formats)
    if (blittable(f.format)) return f;
  throw std::runtime_error("the window surface offers no format that accepts blits");
}

VkPresentModeKHR choosePresentMode(VkPhysicalDevice physical, VkSurfaceKHR surface, bool vsync) {
  if (vsync) return VK_PRESENT_MODE_FIFO_KHR;  // the only mode every implementation has
  uint32_t count = 0;
  GLOBE_VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  GLOBE_VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, modes.data()));
  for (VkPresentModeKHR preferred : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), preferred) != modes.end()) return preferred;
  return VK_PRESENT_MODE_FIFO_KHR;
}

}  // namespace

Swapchain::Swapchain(Device& device, VkExtent2D framebufferExtent, bool vsync) : device_(device), vsync_(vsync) {
  if (device.surface() == VK_NULL_HANDLE) throw std::logic_error("Swapchain needs a Device created with a surface");
  create(framebufferExtent, VK_NULL_HANDLE);
}

void Swapchain::recreate(VkExtent2D framebufferExtent, DeferredReleaseQueue& releases, uint64_t lastUseFrame) {
  State old = std::move(state_);
  state_ = State{};
  create(framebufferExtent, old.swapchain);
  releases.retire(lastUseFrame, std::move(old));
  ++generation_;
}

void Swapchain::create(VkExtent2D framebufferExtent, VkSwapchainKHR old) {
  VkPhysicalDevice physical = device_.physical();
  VkSurfaceKHR surface = device_.surface();
  VkSurfaceCapabilitiesKHR caps;
  GLOBE_VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &caps));
  VkSurfaceFormatKHR format = chooseFormat(physical, surface);
  format_ = format.format;
  colourSpace_ = format.colorSpace;

  // currentExtent is 0xFFFFFFFF when the surface takes its size from the swapchain.
  if (caps.currentExtent.width != UINT32_MAX) {
    extent_ = caps.currentExtent;
  } else {
    extent_.width = std::clamp(framebufferExtent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height = std::clamp(framebufferExtent.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  // One more than the minimum, so the CPU can record a frame while the compositor holds one.
  uint32_t count = caps.minImageCount + 1;
  if (caps.maxImageCount != 0) count = std::min(count, caps.maxImageCount);
  minImageCount_ = std::max(caps.minImageCount, 2u);
  VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if ((caps.supportedUsageFlags & usage) != usage)
    throw std::runtime_error("the window surface does not accept transfer and colour-attachment use");

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface;
  info.minImageCount = std::max(count, minImageCount_);
  info.imageFormat = format.format;
  info.imageColorSpace = format.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = usage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
  info.presentMode = choosePresentMode(physical, surface, vsync_);
  info.clipped = VK_TRUE;
  info.oldSwapchain = old;
  VkDevice dev = device_.device();
  VkSwapchainKHR swapchain;
  GLOBE_VK_CHECK(vkCreateSwapchainKHR(dev, &info, nullptr, &swapchain));
  state_.swapchain = UniqueSwapchain(dev, swapchain);

  uint32_t imageCount = 0;
  GLOBE_VK_CHECK(vkGetSwapchainImagesKHR(dev, swapchain, &imageCount, nullptr));
  state_.images.resize(imageCount);
  GLOBE_VK_CHECK(vkGetSwapchainImagesKHR(dev, swapchain, &imageCount, state_.images.data()));
  for (VkImage image : state_.images) {
    state_.views.push_back(createImageView2D(dev, image, format_, VK_IMAGE_ASPECT_COLOR_BIT));
    state_.renderFinished.push_back(createSemaphore(dev));
    device_.setName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(image), "swapchain image");
  }
}

std::optional<uint32_t> Swapchain::acquire(VkSemaphore acquired) {
  uint32_t index = 0;
  VkResult r = vkAcquireNextImageKHR(device_.device(), state_.swapchain, UINT64_MAX, acquired, VK_NULL_HANDLE, &index);
  if (r == VK_ERROR_OUT_OF_DATE_KHR) return std::nullopt;
  GLOBE_VK_CHECK(r);  // VK_SUBOPTIMAL_KHR still acquired the image and will signal `acquired`
  return index;
}

bool Swapchain::present(uint32_t image) {
  VkSemaphore wait = state_.renderFinished[image];
  VkSwapchainKHR swapchain = state_.swapchain;
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &wait;
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain;
  info.pImageIndices = &image;
  VkResult r = vkQueuePresentKHR(device_.queue(), &info);
  if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) return false;
  GLOBE_VK_CHECK(r);
  return true;
}

}  // namespace globe::vk
