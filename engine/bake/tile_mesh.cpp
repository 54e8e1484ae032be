#include "engine/bake/tile_mesh.h"

#include "planet/camera/camera.h"
#include "planet/tiling/horizon_occlusion.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace globe {

namespace {

// Planet-fixed positions (metres) of every grid sample, apron included, in heights_m order.
std::vector<glm::dvec3> gridPositions(const TileGrid& grid, const Ellipsoid& shape) {
  std::vector<glm::dvec3> directions;
  appendGridDirections(grid.tile, grid.cells, directions);
  for (std::size_t k = 0; k < directions.size(); ++k) directions[k] = shape.position(directions[k], grid.heights_m[k]);
  return directions;
}

std::size_t at(const TileGrid& grid, int i, int j) {
  return std::size_t(j + 1) * std::size_t(grid.side()) + std::size_t(i + 1);
}

glm::dvec3 gridNormal(const TileGrid& grid, const std::vector<glm::dvec3>& p, int i, int j) {
  const glm::dvec3 east = p[at(grid, i + 1, j)] - p[at(grid, i - 1, j)];
  const glm::dvec3 north = p[at(grid, i, j + 1)] - p[at(grid, i, j - 1)];
  // At a pole the east-west samples coincide (up to cos(90 degrees) = 6e-17 rounding): the normal
  // is the outward direction there.
  const double east_m = glm::length(east), north_m = glm::length(north);
  if (east_m < 1e-6 * north_m || north_m < 1e-6 * east_m) return glm::normalize(p[at(grid, i, j)]);
  return glm::normalize(glm::cross(east, north));
}

// The grid's triangles simplified to `error_m` with the border locked; indices into the (cells+1)^2 grid.
std::vector<unsigned> simplifiedTriangles(const TileGrid& grid, const std::vector<glm::dvec3>& p,
                                          const glm::dvec3& origin_m, double error_m, double& achieved_m) {
  const int n = grid.cells;
  const auto row = static_cast<unsigned>(n + 1);
  std::vector<float> local;  // relative to the tile's centre: floats only near their origin
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const glm::dvec3 d = p[at(grid, i, j)] - origin_m;
      local.insert(local.end(), {float(d.x), float(d.y), float(d.z)});
    }
  }
  std::vector<unsigned> indices;
  for (unsigned j = 0; j < unsigned(n); ++j) {
    for (unsigned i = 0; i < unsigned(n); ++i) {
      const unsigned a = j * row + i, b = a + 1, c = a + row + 1, d = a + row;
      indices.insert(indices.end(), {a, b, c, a, c, d});
    }
  }
  const std::size_t vertexCount = local.size() / 3;
  const float scale = meshopt_simplifyScale(local.data(), vertexCount, sizeof(float) * 3);
  std::vector<unsigned> out(indices.size());
  float relative = 0.0f;
  out.resize(meshopt_simplify(out.data(), indices.data(), indices.size(), local.data(), vertexCount, sizeof(float) * 3,
                              0, float(error_m / scale), meshopt_SimplifyLockBorder, &relative));
  achieved_m = double(relative) * double(scale);
  return out;
}

void quantizeHeights(const TileGrid& grid, const std::vector<glm::ivec2>& cells, QuantizedMeshTile& tile) {
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for (const glm::ivec2& c : cells) {
    lo = std::min(lo, grid.height(c.x, c.y));
    hi = std::max(hi, grid.height(c.x, c.y));
  }
  // The header stores floats: round the range outwards so every height stays inside it.
  float lo_f = float(lo), hi_f = float(hi);
  if (double(lo_f) > lo) lo_f = std::nextafter(lo_f, -std::numeric_limits<float>::infinity());
  if (double(hi_f) < hi) hi_f = std::nextafter(hi_f, std::numeric_limits<float>::infinity());
  if (hi_f <= lo_f) hi_f = lo_f + 1.0f;
  tile.header.min_height_m = lo_f;
  tile.header.max_height_m = hi_f;
  const double range = double(hi_f) - double(lo_f);
  for (const glm::ivec2& c : cells) {
    const double q = std::round((grid.height(c.x, c.y) - double(lo_f)) / range * kQuantizedMax);
    tile.height.push_back(static_cast<std::uint16_t>(std::clamp(q, 0.0, double(kQuantizedMax))));
  }
}

std::uint16_t quantizeCoordinate(int i, int cells) {
  return static_cast<std::uint16_t>((std::int64_t(i) * kQuantizedMax * 2 + cells) / (2 * cells));  // rounded
}

}  // namespace

namespace {

// Vertices on each edge (west, south, east, north), ordered along it (by v, then u).
void collectEdges(QuantizedMeshTile& tile) {
  std::array<std::vector<std::pair<std::uint16_t, std::uint32_t>>, 4> sorted;
  for (std::uint32_t k = 0; k < tile.u.size(); ++k) {
    if (tile.u[k] == 0) sorted[0].push_back({tile.v[k], k});
    if (tile.v[k] == 0) sorted[1].push_back({tile.u[k], k});
    if (tile.u[k] == kQuantizedMax) sorted[2].push_back({tile.v[k], k});
    if (tile.v[k] == kQuantizedMax) sorted[3].push_back({tile.u[k], k});
  }
  for (std::size_t e = 0; e < 4; ++e) {
    std::sort(sorted[e].begin(), sorted[e].end());
    for (const auto& [coordinate, index] : sorted[e]) tile.edges[e].push_back(index);
  }
}

// Where a client puts the vertices: u/v over the tile's rectangle, dequantized heights. The bounds
// are computed from these, so they hold for what is drawn.
std::vector<glm::dvec3> decodedPositions(const QuantizedMeshTile& tile, const Ellipsoid& shape, const TileId& id) {
  const GeoRect r = tileRect(id);
  const double range_m = double(tile.header.max_height_m) - double(tile.header.min_height_m);
  std::vector<glm::dvec3> out;
  for (std::size_t k = 0; k < tile.u.size(); ++k) {
    const double lon = r.west_deg + tile.u[k] / double(kQuantizedMax) * (r.east_deg - r.west_deg);
    const double lat = r.south_deg + tile.v[k] / double(kQuantizedMax) * (r.north_deg - r.south_deg);
    const double h = double(tile.header.min_height_m) + tile.height[k] / double(kQuantizedMax) * range_m;
    out.push_back(shape.position(directionFromLatLon(lat, lon), h));
  }
  return out;
}

void setBounds(const std::vector<glm::dvec3>& positions_m, const Ellipsoid& shape, QuantizedMeshTile& tile) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  for (const glm::dvec3& q : positions_m) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  double r = 0.0;
  for (const glm::dvec3& q : positions_m) r = std::max(r, glm::length(q - centre));
  tile.header.center_m = centre;
  tile.header.sphere_center_m = centre;
  tile.header.sphere_radius_m = r;
  // In scaled space (positions / (a, a, b)), where the horizon test is the sphere's.
  const glm::dvec3 radii(shape.equatorialRadius_m(), shape.equatorialRadius_m(), shape.polarRadius_m());
  const glm::dvec3 axis = shape.isSphere() ? glm::normalize(centre) : glm::normalize(centre / radii);
  // The hemisphere-wide root tiles admit no point: a distant one on the axis is hidden only from
  // viewers right behind the planet, who see none of the tile either (docs/bake.md).
  tile.header.horizon_occlusion_point = horizonOcclusionPoint(positions_m, radii, axis).value_or(axis * 1.0e3);
}

}  // namespace

QuantizedMeshTile buildTileMesh(const TileGrid& grid, const Ellipsoid& shape, double error_m, TileMeshStats* stats) {
  const int n = grid.cells;
  const std::vector<glm::dvec3> p = gridPositions(grid, shape);
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      lo = glm::min(lo, p[at(grid, i, j)]);
      hi = glm::max(hi, p[at(grid, i, j)]);
    }
  }
  double achieved_m = 0.0;
  const std::vector<unsigned> triangles = simplifiedTriangles(grid, p, 0.5 * (lo + hi), error_m, achieved_m);

  QuantizedMeshTile tile;
  const auto row = static_cast<unsigned>(n + 1);
  std::vector<std::uint32_t> remap(std::size_t(row) * row, ~0u);
  std::vector<glm::ivec2> kept;  // grid (i, j) of each vertex, in order of first use
  for (unsigned g : triangles) {
    if (remap[g] == ~0u) {
      remap[g] = static_cast<std::uint32_t>(kept.size());
      kept.push_back({int(g % row), int(g / row)});
    }
    tile.indices.push_back(remap[g]);
  }
  for (const glm::ivec2& c : kept) {
    tile.u.push_back(quantizeCoordinate(c.x, n));
    tile.v.push_back(quantizeCoordinate(c.y, n));
    tile.normals.push_back(octEncode(gridNormal(grid, p, c.x, c.y)));
  }
  quantizeHeights(grid, kept, tile);
  collectEdges(tile);
  setBounds(decodedPositions(tile, shape, grid.tile), shape, tile);
  if (stats != nullptr) *stats = {std::size_t(row) * row, kept.size(), triangles.size() / 3, achieved_m};
  return tile;
}

}  // namespace globe
