#include "planet/elevation/layer_evaluation.h"

namespace globe {

std::uint32_t layerSeed(std::uint64_t planet_seed, int layer_index) {
  const auto lo = static_cast<std::uint32_t>(planet_seed & 0xffffffffULL);
  const auto hi = static_cast<std::uint32_t>(planet_seed >> 32);
  const auto index = static_cast<std::uint32_t>(layer_index + 1);
  return hashMix32(hashMix32(lo + 0x85ebca6bU * index) ^ hashMix32(hi + 0xc2b2ae35U));
}

ElevationSpecialization elevationSpecialization(const gpu::ElevationParams& params) {
  ElevationSpecialization s{};
  s[GLOBE_ELEVATION_SPEC_LAYER_COUNT] = params.layer_count;
  for (int l = 0; l < GLOBE_MAX_ELEVATION_LAYERS; ++l) {
    const gpu::ElevationLayerParams& layer = params.layers[l];
    s[GLOBE_ELEVATION_SPEC_OCTAVES + l] = layer.octaves;
    s[GLOBE_ELEVATION_SPEC_KIND + l] = layer.kind;
    s[GLOBE_ELEVATION_SPEC_MODULATOR + l] = static_cast<std::uint32_t>(layer.modulator);
  }
  s[GLOBE_ELEVATION_SPEC_ELLIPSOID] = params.polar_radius_m != params.radius_m ? 1U : 0U;
  return s;
}

}  // namespace globe
