#pragma once
// The CPU reference of a payload's normal map (shaders/include/payload_layout.h,
// shaders/include/normal_map.glsl): the texels' directions, elevations, double normals and colour
// ramp the payload kernel computes, and the texel packing. Tests compare the GPU's maps with it;
// fillPayloadReference fills the map of slots with a normal map.
#include "planet/elevation/elevation.h"
#include "shaders/include/payload_layout.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace globe {

// Texels of a map with `mapCells` cells per side, both levels (GLOBE_NORMAL_MAP_TEXELS).
inline size_t normalMapTexelCount(uint32_t mapCells) { return GLOBE_NORMAL_MAP_TEXELS(mapCells); }

// One texel before packing: the unit normal in double and the linear albedo.
struct NormalMapTexel {
  glm::dvec3 normal{0.0};
  glm::vec3 albedo{0.0f};
};

// The map of `job`'s node with `cells` grid cells and map scale `scale` (1, 2, 4), texels in the
// layout's order (level 0, then level 1). Procedural elevation only: on a planet with sources the
// kernel also blends the mesh samples' source terms, which this reference does not.
// `waterSurface`: as the kernel's switch (texels below sea level lie on the sea surface).
std::vector<NormalMapTexel> normalMapReference(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                                               uint32_t scale, bool waterSurface = false);

// The packed texel (normal_map.glsl's packNormalMapTexel) and its decoded normal and linear albedo.
glm::uvec2 packNormalMapTexel(const NormalMapTexel& texel);
glm::dvec3 normalMapTexelNormal(glm::uvec2 packed);
glm::vec3 normalMapTexelAlbedo(glm::uvec2 packed);

}  // namespace globe
