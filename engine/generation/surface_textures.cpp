#include "engine/generation/surface_textures.h"

#include "engine/vk/resources.h"
#include "engine/vk/vk_check.h"
#include "shaders/include/payload_layout.h"

#include <algorithm>
#include <cassert>

namespace globe {
namespace {

constexpr std::array<VkFormat, 2> kFormats{kSurfaceNormalsFormat, kSurfaceAlbedoFormat};
constexpr std::array<const char*, 2> kNames{"surface normals", "surface albedo"};

constexpr uint32_t kMips = 2;  // the node's map and its parent's over its quadrant (payload_layout.h)

vk::UniqueImage createLayers(vk::Device& device, VkFormat format, uint32_t side, uint32_t layers, const char* name) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {side, side, 1};
  info.mipLevels = kMips;
  info.arrayLayers = layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  // Transfer source: tests and tools read layers back.
  info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image;
  GLOBE_VK_CHECK(vkCreateImage(device.device(), &info, nullptr, &image));
  device.setName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(image), name);
  return vk::UniqueImage(device.device(), image);
}

// Mips [firstMip, firstMip + mips) of every layer.
vk::UniqueImageView createLayersView(VkDevice device, VkImage image, VkFormat format, uint32_t layers,
                                     uint32_t firstMip, uint32_t mips) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image;
  info.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
  info.format = format;
  info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, firstMip, mips, 0, layers};
  VkImageView view;
  GLOBE_VK_CHECK(vkCreateImageView(device, &info, nullptr, &view));
  return vk::UniqueImageView(device, view);
}

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

size_t SurfaceTextures::bytesPerSlot(uint32_t mapCells) {
  return size_t(GLOBE_NORMAL_MAP_TEXELS(mapCells)) * 2 * 4;  // both mips, two RGBA8 texels
}

SurfaceTextures::SurfaceTextures(vk::Device& device, uint32_t mapCells, uint32_t slots, uint32_t slotsPerPage)
    : mapCells_(mapCells) {
  if (mapCells > 0) {
    side_ = GLOBE_SURFACE_TEXTURE_SIDE(mapCells);
  } else {
    slots = slotsPerPage = 1;
  }
  assert(slotsPerPage > 0);
  for (uint32_t first = 0; first < std::max(slots, 1u); first += slotsPerPage)
    pages_.push_back(makePage(device, std::min(slotsPerPage, std::max(slots, 1u) - first)));
  sampler_ = createClampSampler(device.device());
  // Once, before any kernel writes: both images of every page to GENERAL for good.
  device.submitAndWait([&](VkCommandBuffer cmd) {
    for (const Page& page : pages_)
      for (const vk::UniqueImage& image : page.images)
        vk::transitionImage(cmd, image, {VK_IMAGE_ASPECT_COLOR_BIT, 0, kMips, 0, VK_REMAINING_ARRAY_LAYERS},
                            VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
  });
}

SurfaceTextures::Page SurfaceTextures::makePage(vk::Device& device, uint32_t layers) const {
  Page page;
  // One allocation for both images: the normals first, the albedo at its alignment after them.
  std::array<VkMemoryRequirements, 2> req{};
  for (size_t i = 0; i < 2; ++i) {
    page.images[i] = createLayers(device, kFormats[i], side_, layers, kNames[i]);
    vkGetImageMemoryRequirements(device.device(), page.images[i], &req[i]);
  }
  const VkDeviceSize second = (req[0].size + req[1].alignment - 1) / req[1].alignment * req[1].alignment;
  VkMemoryRequirements both = req[0];
  both.size = second + req[1].size;
  both.memoryTypeBits = req[0].memoryTypeBits & req[1].memoryTypeBits;
  page.memory = vk::allocateMemory(device, both, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  GLOBE_VK_CHECK(vkBindImageMemory(device.device(), page.images[0], page.memory, 0));
  GLOBE_VK_CHECK(vkBindImageMemory(device.device(), page.images[1], page.memory, second));
  for (size_t i = 0; i < 2; ++i) {
    page.views[i] = createLayersView(device.device(), page.images[i], kFormats[i], layers, 0, kMips);
    for (uint32_t mip = 0; mip < kMips; ++mip)
      page.storageViews[2 * mip + i] = createLayersView(device.device(), page.images[i], kFormats[i], layers, mip, 1);
  }
  return page;
}

std::array<vk::ImageDescriptor, 4> SurfaceTextures::storage(uint32_t page) const {
  static_assert(GLOBE_PAYLOAD_ALBEDO_BINDING == GLOBE_PAYLOAD_NORMALS_BINDING + 1 &&
                GLOBE_PAYLOAD_PARENT_NORMALS_BINDING == GLOBE_PAYLOAD_NORMALS_BINDING + 2 &&
                GLOBE_PAYLOAD_PARENT_ALBEDO_BINDING == GLOBE_PAYLOAD_NORMALS_BINDING + 3);
  std::array<vk::ImageDescriptor, 4> images;
  for (uint32_t k = 0; k < 4; ++k)
    images[k] = {{GLOBE_PAYLOAD_NORMALS_BINDING + k, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                 {VK_NULL_HANDLE, pages_[page].storageViews[k], VK_IMAGE_LAYOUT_GENERAL}};
  return images;
}

std::array<vk::ImageDescriptor, 2> SurfaceTextures::sampled(uint32_t page, uint32_t normalsBinding) const {
  const Page& p = pages_[page];
  return {vk::ImageDescriptor{{normalsBinding}, {sampler_, p.views[0], VK_IMAGE_LAYOUT_GENERAL}},
          vk::ImageDescriptor{{normalsBinding + 1}, {sampler_, p.views[1], VK_IMAGE_LAYOUT_GENERAL}}};
}

}  // namespace globe
