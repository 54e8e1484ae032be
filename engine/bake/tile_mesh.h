#pragma once
// One quantized-mesh tile from a height grid: the grid's triangles simplified with meshoptimizer to
// the level's geometric error [Kapoulkine 2017] with the tile's border locked, so every edge keeps
// all of its grid vertices and the neighbour across it has exactly the same ones (u/v identical,
// heights from the same double samples); normals from the surface by central differences.
#include "engine/bake/quantized_mesh.h"
#include "engine/bake/tile_grid.h"
#include "planet/geometry/ellipsoid.h"

namespace globe {

struct TileMeshStats {
  std::size_t grid_vertices = 0;
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  double simplification_error_m = 0.0;  // meshoptimizer's estimate, metres
};

// `error_m`: the largest deviation the simplification may introduce; `shape`: the planet's sphere or
// ellipsoid (heights are along its normals at geodetic latitude/longitude, as Cesium reads them).
QuantizedMeshTile buildTileMesh(const TileGrid& grid, const Ellipsoid& shape, double error_m,
                                TileMeshStats* stats = nullptr);

}  // namespace globe
