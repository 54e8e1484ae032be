#pragma once
// The land-cover classes' detail textures on the GPU: one 2-D array image (a layer per class, the
// full mip chain) and the sampler the terrain shader reads it with (trilinear, repeating). The
// texels are made on the CPU (planet/surface/detail_texture.h); loadDetailTextures adds the
// classes' own PNG files.
#include "engine/vk/device.h"
#include "engine/vk/vk_handles.h"
#include "planet/core/error.h"
#include "planet/surface/detail_texture.h"

#include <cstdint>

namespace globe {

class DetailTextureArray {
 public:
  // Creates the image and uploads every mip of every layer (one staging buffer, one submit that
  // is waited for); the image ends in SHADER_READ_ONLY_OPTIMAL. `textures` needs its full mip chain.
  DetailTextureArray(vk::Device& device, const DetailTextureSet& textures);

  // The view (2D_ARRAY) and sampler, for a combined image sampler read in SHADER_READ_ONLY_OPTIMAL.
  VkDescriptorImageInfo descriptor() const { return {sampler_, view_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}; }
  VkImage image() const { return image_; }
  uint32_t layers() const { return layers_; }
  uint32_t mipLevels() const { return mipLevels_; }

 private:
  void upload(vk::Device& device, const DetailTextureSet& textures);

  vk::UniqueMemory memory_;  // declared first: destroyed after the image bound to it
  vk::UniqueImage image_;
  vk::UniqueImageView view_;
  vk::UniqueSampler sampler_;
  uint32_t size_ = 0;
  uint32_t layers_ = 0;
  uint32_t mipLevels_ = 0;
};

// The detail textures of `cover` on a planet of `seed`: the procedural layer of every class, then
// each class's `texture` PNG (if it names one) in its layer, taken relative to its mean colour, then
// the mips. An unreadable PNG is an Error naming the file and the field ("land_cover[2].texture").
Result<DetailTextureSet> loadDetailTextures(const LandCover& cover, std::uint64_t seed);

}  // namespace globe
