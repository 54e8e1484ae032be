#pragma once
// One drawn node's instance record (shaders/include/terrain_layout.h), as the terrain's draws and
// its shadow maps' read it: the same position and morph in both, so a surface meets its own depth
// in the shadow map.
#include "engine/generation/payload_pages.h"
#include "shaders/include/terrain_layout.h"

#include <glm/glm.hpp>

namespace globe {

struct DrawNode;  // terrain_renderer.h

// A float morph distance: +infinity (depth 0 never morphs) and anything beyond float become
// FLT_MAX, which the shader treats as "never".
float morphDistance(double metres);
gpu::TerrainVec4 toGpu(const glm::vec3& v, float w);

// The record of `n` drawn with the floating origin `origin_m`: its payload slot, offset, morph band,
// level and face frame. The imagery and land cover fields are the caller's.
gpu::TerrainInstance terrainInstance(const DrawNode& n, const glm::dvec3& origin_m, const PayloadPages& payloads,
                                     uint32_t gridCells);

}  // namespace globe
