#include "engine/render/terrain_instance.h"

#include "engine/render/terrain_renderer.h"
#include "planet/geometry/face_mapping.h"
#include "shaders/include/payload_layout.h"

#include <limits>

namespace globe {

float morphDistance(double metres) {
  if (!(metres < double(std::numeric_limits<float>::max()))) return std::numeric_limits<float>::max();
  return float(metres);
}

gpu::TerrainVec4 toGpu(const glm::vec3& v, float w) { return {v.x, v.y, v.z, w}; }

gpu::TerrainInstance terrainInstance(const DrawNode& n, const glm::dvec3& origin_m, const PayloadPages& payloads,
                                     uint32_t gridCells) {
  gpu::TerrainInstance inst{};
  // Double first, float last: the offset is a multiple of the level's quantum and small.
  inst.offset = toGpu(glm::vec3(n.centre_m - origin_m), 0.0f);
  inst.morph = {morphDistance(n.morph.startFloor_m), morphDistance(n.morph.ownRange_m), float(n.morph.fraction), 0.0f};
  inst.morphEnd = {morphDistance(n.morph.end_m[0]), morphDistance(n.morph.end_m[1]), morphDistance(n.morph.end_m[2]),
                   morphDistance(n.morph.end_m[3])};
  inst.info = {payloads.localSlot(n.slot) * GLOBE_PAYLOAD_SLOT_VEC4(gridCells), n.partial ? 2u : 1u,
               uint32_t(n.id.level) - (n.partial ? 1u : 0u), 0u};
  const std::array<glm::dvec3, 3>& frame = RhombusFaceMapping::get().faceFrame(n.id.face);
  inst.frameEast = toGpu(glm::vec3(frame[0]), 0.0f);
  inst.frameUp = toGpu(glm::vec3(frame[2]), 0.0f);
  return inst;
}

}  // namespace globe
