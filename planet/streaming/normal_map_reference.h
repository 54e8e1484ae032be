#pragma once
// The CPU reference of a payload's surface textures (shaders/include/payload_layout.h): the texels'
// directions, elevations, double normals, coast field and colour ramp the payload kernel computes.
// Tests compare the GPU's textures with it.
#include "planet/model/elevation_model.h"
#include "shaders/include/payload_layout.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

namespace globe {

// Texels of a map with `mapCells` cells per side, both mips (GLOBE_NORMAL_MAP_TEXELS).
inline size_t normalMapTexelCount(uint32_t mapCells) { return GLOBE_NORMAL_MAP_TEXELS(mapCells); }

// One texel before it is stored: the unit normal in double, the linear albedo and the coast field
// (ground above sea level in GLOBE_SURFACE_COAST_SCALE texel widths of its level, clamped to [-1, 1]).
struct NormalMapTexel {
  glm::dvec3 normal{0.0};
  glm::vec3 albedo{0.0f};
  float coast = 0.0f;
  glm::vec4 colourLayer{0.0f};  // with an overlay: the colour layer's texel, linear (overlaidTexel)
};

// The surface textures of `job`'s node with `cells` grid cells and map scale `scale` (1, 2, 4, 8):
// mip 0's texels row by row, then mip 1's (payload_layout.h). Procedural elevation only: on a planet with sources the
// kernel also blends the mesh samples' source terms, which this reference does not.
// `waterSurface`: as the kernel's switch (texels under the sea take their colour from the land beside them,
// colourElevation; their normals are the ground's either way).
std::vector<NormalMapTexel> normalMapReference(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                                               uint32_t scale, bool waterSurface = false);

}  // namespace globe
