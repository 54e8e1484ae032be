#pragma once
// The payload slots' surface textures (shaders/include/payload_layout.h): per payload page two 2-D
// array images of two mips with one layer per slot of the page, allocated once with the pool. The
// payload kernel writes both mips of a slot's layer as storage images; the terrain's fragment stages
// sample them with one trilinear fetch, the LOD being the morph factor (docs/rendering.md, "Surface
// textures").
// The images stay in the GENERAL layout: written and sampled without transitions, so a slot can be
// regenerated while other layers of its page are drawn.
#include "engine/vk/compute_pipeline.h"
#include "engine/vk/device.h"
#include "engine/vk/vk_handles.h"

#include <array>
#include <cstdint>
#include <vector>

namespace globe {

// Formats: normals and the coast field, the square root of the albedo: both 8-bit UNORM, the
// format lavapipe filters on its fast path (RGBA16_SNORM normals made the flyover's terrain pass 2x
// slower there: docs/rendering.md, "Surface textures").
inline constexpr VkFormat kSurfaceNormalsFormat = VK_FORMAT_R8G8B8A8_UNORM;
inline constexpr VkFormat kSurfaceAlbedoFormat = VK_FORMAT_R8G8B8A8_UNORM;

class SurfaceTextures {
 public:
  // Bytes one slot's layers take (both images) for `mapCells` map cells per side; 0 without maps.
  static size_t bytesPerSlot(uint32_t mapCells);

  SurfaceTextures() = default;
  // Images for `slots` slots in pages of `slotsPerPage` layers (the last page holds the rest).
  // mapCells 0: one 2 x 2 layer per image, bound but never written (kernels without maps).
  SurfaceTextures(vk::Device& device, uint32_t mapCells, uint32_t slots, uint32_t slotsPerPage);

  uint32_t pageCount() const { return uint32_t(pages_.size()); }
  uint32_t mapCells() const { return mapCells_; }
  // The page's images as the payload kernel writes them: normals and albedo of mip 0, then of mip 1
  // (GLOBE_PAYLOAD_NORMALS_BINDING on).
  std::array<vk::ImageDescriptor, 4> storage(uint32_t page) const;
  // The page's images as the fragment stages sample them, at `normalsBinding` and the next binding.
  std::array<vk::ImageDescriptor, 2> sampled(uint32_t page, uint32_t normalsBinding) const;
  // The page's images (tests read layers back).
  VkImage normalsImage(uint32_t page) const { return pages_[page].images[0]; }
  VkImage albedoImage(uint32_t page) const { return pages_[page].images[1]; }
  uint32_t side() const { return side_; }  // mip 0's texels per side (mip 1: side() / 2)

 private:
  struct Page {
    vk::UniqueMemory memory;  // declared first: destroyed after the images bound to it
    std::array<vk::UniqueImage, 2> images;
    std::array<vk::UniqueImageView, 2> views;         // both mips, sampled
    std::array<vk::UniqueImageView, 4> storageViews;  // one mip each: normals 0, albedo 0, normals 1, albedo 1
  };
  Page makePage(vk::Device& device, uint32_t layers) const;

  uint32_t mapCells_ = 0;
  uint32_t side_ = 2;
  std::vector<Page> pages_;
  vk::UniqueSampler sampler_;
};

}  // namespace globe
