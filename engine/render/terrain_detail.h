#pragma once
// How the land cover's detail textures tile the terrain (terrain_fragment.glsl): each face's (u, v)
// square is cut like the quadtree, and a node of `fineLevel` (coarseLevel) is one tile of the fine
// (coarse) texture. The tiles' coordinates then continue from node to node and from level to level
// (a node of level l spans 2^(L - l) tiles, or the part of one its index gives), they are exact in
// float near the camera whatever the planet's size, and they need no planet-scale number on the GPU.
// They break only along the 30 face seams, where the faces' (u, v) axes turn.
#include "planet/geometry/node_id.h"

#include <glm/vec4.hpp>

namespace globe {

struct TerrainDetailTiling {
  int fineLevel = 20;    // a tile of 2..4 m (kFineTile_m)
  int coarseLevel = 15;  // 32 fine tiles
};

// Target width of a fine tile, metres: fine enough for 2 m views, the coarse one breaks its repeats.
inline constexpr double kFineTile_m = 4.0;

// The levels for a planet of `radius_m`: the fine tile at most kFineTile_m wide.
TerrainDetailTiling detailTilingFor(double radius_m);

// TerrainInstance::detail: where `id`'s (u, v) corner falls in the fine (xy) and coarse (zw) tiles.
glm::vec4 detailTileOffsets(const NodeId& id, const TerrainDetailTiling& tiling);

}  // namespace globe
