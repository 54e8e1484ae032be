#include "engine/generation/surface_textures.h"

#include "engine/vk/resources.h"
#include "engine/vk/vk_check.h"
#include "shaders/include/payload_layout.h"

#include <algorithm>
#include <cassert>

namespace globe {
namespace {

constexpr uint32_t kMips = 2;  // the node's map and its parent's over its quadrant (payload_layout.h)

// Trilinear, clamped: the fragment stages give the LOD (the morph factor) and address the node's own
// cells, whose bilinear footprint stays inside the gutter.
vk::UniqueSampler createClampSampler(VkDevice device) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  info.maxLod = float(kMips - 1);
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxAnisotropy = 1.0f;
  VkSampler sampler;
  GLOBE_VK_CHECK(vkCreateSampler(device, &info, nullptr, &sampler));
  return vk::UniqueSampler(device, sampler);
}

}  // namespace

size_t SurfaceTextures::bytesPerSlot(uint32_t mapCells, uint32_t layersPerSlot) {
  return size_t(GLOBE_NORMAL_MAP_TEXELS(mapCells)) * 4 * layersPerSlot;  // both mips, RGBA8
}

SurfaceTextures::SurfaceTextures(vk::Device& device, uint32_t mapCells, uint32_t slots, uint32_t slotsPerPage,
                                 uint32_t layersPerSlot)
    : mapCells_(mapCells), layersPerSlot_(mapCells > 0 ? layersPerSlot : 1) {
  if (mapCells > 0) {
    side_ = GLOBE_SURFACE_TEXTURE_SIDE(mapCells);
  } else {
    slots = slotsPerPage = 1;
  }
  assert(slotsPerPage > 0);
  for (uint32_t first = 0; first < std::max(slots, 1u); first += slotsPerPage)
    pages_.push_back(makePage(device, std::min(slotsPerPage, std::max(slots, 1u) - first) * layersPerSlot_));
  sampler_ = createClampSampler(device.device());
  // Once, before any kernel writes: every page's image to GENERAL for good.
  device.submitAndWait([&](VkCommandBuffer cmd) {
    for (const Page& page : pages_)
      vk::transitionImage(cmd, page.image, {VK_IMAGE_ASPECT_COLOR_BIT, 0, kMips, 0, VK_REMAINING_ARRAY_LAYERS},
                          VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
  });
}

SurfaceTextures::Page SurfaceTextures::makePage(vk::Device& device, uint32_t layers) const {
  Page page;
  // Transfer source: tests and tools read layers back.
  page.image = vk::createImage(
      device, kSurfaceFormat, {side_, side_}, layers, kMips, VK_SAMPLE_COUNT_1_BIT,
      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "surface textures");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device.device(), page.image, &req);
  page.memory = vk::allocateMemory(device, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  GLOBE_VK_CHECK(vkBindImageMemory(device.device(), page.image, page.memory, 0));
  page.view = vk::createArrayView(device.device(), page.image, kSurfaceFormat, layers, 0, kMips);
  for (uint32_t mip = 0; mip < kMips; ++mip)
    page.storageViews[mip] = vk::createArrayView(device.device(), page.image, kSurfaceFormat, layers, mip, 1);
  return page;
}

std::array<vk::ImageDescriptor, 2> SurfaceTextures::storage(uint32_t page) const {
  static_assert(GLOBE_PAYLOAD_PARENT_SURFACE_BINDING == GLOBE_PAYLOAD_SURFACE_BINDING + 1);
  std::array<vk::ImageDescriptor, 2> images;
  for (uint32_t mip = 0; mip < kMips; ++mip)
    images[mip] = {{GLOBE_PAYLOAD_SURFACE_BINDING + mip, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                   {VK_NULL_HANDLE, pages_[page].storageViews[mip], VK_IMAGE_LAYOUT_GENERAL}};
  return images;
}

vk::ImageDescriptor SurfaceTextures::sampled(uint32_t page, uint32_t binding) const {
  return {{binding}, {sampler_, pages_[page].view, VK_IMAGE_LAYOUT_GENERAL}};
}

}  // namespace globe
