#pragma once
// The payload slots' surface texture (shaders/include/payload_layout.h): per payload page one 2-D
// array image of two mips with one layer per slot of the page (two on a planet with an overlay: the
// colour layer follows), allocated once with the pool. The
// payload kernel writes both mips of a slot's layer as storage images; the terrain's fragment stages
// sample it with one trilinear fetch, the LOD being the morph factor (docs/rendering.md, "Surface
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

// 8-bit UNORM, the format lavapipe filters on its fast path (docs/rendering.md, "Surface textures").
inline constexpr VkFormat kSurfaceFormat = VK_FORMAT_R8G8B8A8_UNORM;

class SurfaceTextures {
 public:
  // Bytes one slot's layers take (both mips) for `mapCells` map cells per side; 0 without maps.
  static size_t bytesPerSlot(uint32_t mapCells, uint32_t layersPerSlot = 1);

  SurfaceTextures() = default;
  // Images for `slots` slots in pages of `slotsPerPage` slots (the last page holds the rest), each
  // slot `layersPerSlot` layers: 1, or 2 with the colour layer after each slot's surface layer (a
  // planet with an overlay, payload_layout.h). mapCells 0: one 2 x 2 layer, bound but never written
  // (kernels without maps).
  SurfaceTextures(vk::Device& device, uint32_t mapCells, uint32_t slots, uint32_t slotsPerPage,
                  uint32_t layersPerSlot = 1);

  uint32_t pageCount() const { return uint32_t(pages_.size()); }
  uint32_t mapCells() const { return mapCells_; }
  // The page's image as the payload kernel writes it: mip 0, mip 1 (GLOBE_PAYLOAD_SURFACE_BINDING on).
  std::array<vk::ImageDescriptor, 2> storage(uint32_t page) const;
  // The page's image as the fragment stages sample it, at `binding`.
  vk::ImageDescriptor sampled(uint32_t page, uint32_t binding) const;
  // The page's image (tests read layers back).
  VkImage image(uint32_t page) const { return pages_[page].image; }
  uint32_t side() const { return side_; }  // mip 0's texels per side (mip 1: side() / 2)
  // Layers a slot takes: slot k's surface layer is k * layersPerSlot(), its colour layer the next.
  uint32_t layersPerSlot() const { return layersPerSlot_; }

 private:
  struct Page {
    vk::UniqueMemory memory;  // declared first: destroyed after the image bound to it
    vk::UniqueImage image;
    vk::UniqueImageView view;                         // both mips, sampled
    std::array<vk::UniqueImageView, 2> storageViews;  // one mip each
  };
  Page makePage(vk::Device& device, uint32_t layers) const;

  uint32_t mapCells_ = 0;
  uint32_t side_ = 2;
  uint32_t layersPerSlot_ = 1;
  std::vector<Page> pages_;
  vk::UniqueSampler sampler_;
};

}  // namespace globe
