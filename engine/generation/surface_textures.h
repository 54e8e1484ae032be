#pragma once
// The payload slots' surface textures (shaders/include/payload_layout.h): per payload page two 2-D
// array images with one layer per slot of the page, allocated once with the pool. The payload kernel
// writes a slot's layer as storage images; the terrain's fragment stages sample it with the sampler's
// bilinear filtering (no hand-made filtering of buffer words: docs/rendering.md, "Surface textures").
// The images stay in the GENERAL layout: written and sampled without transitions, so a slot can be
// regenerated while other layers of its page are drawn.
#include "engine/vk/compute_pipeline.h"
#include "engine/vk/device.h"
#include "engine/vk/vk_handles.h"

#include <array>
#include <cstdint>
#include <vector>

namespace globe {

// Formats: normals and the coast field (signed 16-bit), the square root of the albedo (8-bit).
inline constexpr VkFormat kSurfaceNormalsFormat = VK_FORMAT_R16G16B16A16_SNORM;
inline constexpr VkFormat kSurfaceAlbedoFormat = VK_FORMAT_R8G8B8A8_UNORM;

class SurfaceTextures {
 public:
  // Bytes one slot's layers take (both images) for `mapCells` map cells per side; 0 without maps.
  static size_t bytesPerSlot(uint32_t mapCells);

  SurfaceTextures() = default;
  // Images for `slots` slots in pages of `slotsPerPage` layers (the last page holds the rest).
  // mapCells 0: one 1 x 1 layer per image, bound but never written (kernels without maps).
  SurfaceTextures(vk::Device& device, uint32_t mapCells, uint32_t slots, uint32_t slotsPerPage);

  uint32_t pageCount() const { return uint32_t(pages_.size()); }
  uint32_t mapCells() const { return mapCells_; }
  // The page's images as the payload kernel writes them (GLOBE_PAYLOAD_NORMALS_BINDING, _ALBEDO_).
  std::array<vk::ImageDescriptor, 2> storage(uint32_t page) const;
  // The page's images as the fragment stages sample them, at `normalsBinding` and the next binding.
  std::array<vk::ImageDescriptor, 2> sampled(uint32_t page, uint32_t normalsBinding) const;
  // The page's images (tests read layers back).
  VkImage normalsImage(uint32_t page) const { return pages_[page].images[0]; }
  VkImage albedoImage(uint32_t page) const { return pages_[page].images[1]; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  struct Page {
    vk::UniqueMemory memory;  // declared first: destroyed after the images bound to it
    std::array<vk::UniqueImage, 2> images;
    std::array<vk::UniqueImageView, 2> views;
  };
  Page makePage(vk::Device& device, uint32_t layers) const;

  uint32_t mapCells_ = 0;
  uint32_t width_ = 1, height_ = 1;
  std::vector<Page> pages_;
  vk::UniqueSampler sampler_;
};

}  // namespace globe
