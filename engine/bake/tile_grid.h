#pragma once
// The height samples of one tile: a regular (cells + 1)^2 grid over its longitude/latitude rectangle
// with one sample of apron on every side (for the normals of edge vertices), so (cells + 3)^2 in all.
// Sample (i, j), i eastwards and j northwards in [-1, cells + 1], sits at tileSampleLonLat.
#include "planet/tiling/geographic_tiling.h"

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

namespace globe {

inline constexpr int kMeshCells = 64;  // 65 x 65 vertices before simplification, as Cesium's heightmaps

struct TileGrid {
  TileId tile;
  int cells = kMeshCells;
  std::vector<double> heights_m;  // (cells + 3)^2, row-major from the south-west apron corner

  int side() const { return cells + 3; }
  double height(int i, int j) const { return heights_m[std::size_t(j + 1) * std::size_t(side()) + std::size_t(i + 1)]; }
};

// The unit directions of every sample of a tile's grid, in heights_m order, appended to `out`.
void appendGridDirections(const TileId& tile, int cells, std::vector<glm::dvec3>& out);

}  // namespace globe
