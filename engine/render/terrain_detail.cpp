#include "engine/render/terrain_detail.h"

#include "planet/geometry/face_mapping.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace globe {

TerrainDetailTiling detailTilingFor(double radius_m) {
  const RhombusFaceMapping& mapping = RhombusFaceMapping::get();
  // A face's edge on the planet, metres (the faces are congruent).
  const double edge_m =
      radius_m *
      std::acos(std::clamp(glm::dot(mapping.unitPoint(0, 0.0, 0.0), mapping.unitPoint(0, 1.0, 0.0)), -1.0, 1.0));
  TerrainDetailTiling t;
  t.fineLevel = std::clamp(int(std::ceil(std::log2(edge_m / kFineTile_m))), 5, int(kMaxNodeLevel));
  t.coarseLevel = t.fineLevel - 5;
  return t;
}

namespace {

// The fraction of a tile of `tileLevel` before the node's index `i` at `level`.
float tileOffset(uint32_t i, int level, int tileLevel) {
  if (level <= tileLevel) return 0.0f;  // the node spans whole tiles
  const int finer = level - tileLevel;
  const uint32_t within = i & ((1u << finer) - 1u);
  return float(std::ldexp(double(within), -finer));
}

}  // namespace

glm::vec4 detailTileOffsets(const NodeId& id, const TerrainDetailTiling& tiling) {
  const int level = int(id.level);
  return {tileOffset(id.x, level, tiling.fineLevel), tileOffset(id.y, level, tiling.fineLevel),
          tileOffset(id.x, level, tiling.coarseLevel), tileOffset(id.y, level, tiling.coarseLevel)};
}

}  // namespace globe
