#pragma once
// The land-cover classes' tiled detail textures, on the CPU (engine/render/detail_texture_array.h
// uploads them). The terrain shader multiplies a class's colour by 2 * texel, so a texture holds a
// *modulation* whose mean is 0.5 per channel: the class colour stays the mean colour at every
// distance and at the coarsest mip. Sampled with REPEAT addressing, so every layer tiles seamlessly.
#include <cstdint>
#include <span>
#include <vector>

#include "planet/surface/land_cover.h"

namespace globe {

// One layer per class, RGBA8 UNORM (linear, not sRGB), with the full mip chain down to 1x1.
// mips[m] holds every layer, layer after layer, each (size >> m)^2 texels of 4 bytes, rows top down.
// Alpha is the luminance modulation (the RGB's luminance).
struct DetailTextureSet {
  uint32_t size = 0;    // level 0's width and height, a power of two
  uint32_t layers = 0;  // >= 1
  std::vector<std::vector<std::uint8_t>> mips;
};

// One procedural layer per class (one flat layer when there are none), with its mips: tileable
// fBm of periodic gradient noise, contrast from the class's detail_contrast (0 = flat 0.5), a slight
// hue variation per channel, seeded from `planetSeed` and the class index. Deterministic. Level 0's
// mean per RGB channel is 0.5 (within half a step of 8 bits) in every layer. `size`: a power of two.
DetailTextureSet proceduralDetailTextures(const LandCover& cover, std::uint64_t planetSeed, uint32_t size = 256);

// Replaces level 0 of `layer` by a user's image (`linearRgba`: width * height * 4 linear floats, row
// 0 at the top): resampled to size x size (box filter when shrinking, bilinear with wrap-around when
// growing), each RGB channel divided by its mean and scaled to 0.5 (clamped to [0, 1]), so the image
// keeps its pattern and the class colour sets the mean. Call buildDetailMips afterwards.
void setDetailLayerFromImage(DetailTextureSet& set, uint32_t layer, uint32_t width, uint32_t height,
                             std::span<const float> linearRgba);

// Rebuilds mips[1..] from level 0: 2x2 box filter, computed in float from level 0 so every level
// keeps level 0's mean (each level rounds once, not once per level).
void buildDetailMips(DetailTextureSet& set);

}  // namespace globe
