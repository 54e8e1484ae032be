#pragma once
// A quantized-mesh-1.0 reader [Cesium 2014], written from the format's description independently
// of the encoder (engine/bake/quantized_mesh.cpp) so that the two check each other in the tests:
// zig-zag deltas, high-water-mark indices, 16/32-bit indices and their alignment, edges,
// extensions. Baked tilesets read back as elevation sources use it too
// (planet/sources/baked_tileset_driver.cpp).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace globe {

struct DecodedMesh {
  glm::dvec3 center{0.0};
  float min_height = 0, max_height = 0;
  glm::dvec3 sphere_center{0.0};
  double sphere_radius = 0;
  glm::dvec3 horizon_point{0.0};
  std::vector<int> u, v, h;  // [0, 32767]
  std::vector<std::uint32_t> indices;
  std::array<std::vector<std::uint32_t>, 4> edges;  // west, south, east, north
  std::vector<glm::dvec3> normals;                  // decoded oct normals (unit)
  bool has_normals = false;

  double height_m(std::size_t k) const {
    return double(min_height) + h[k] / 32767.0 * (double(max_height) - double(min_height));
  }
  double heightStep_m() const { return (double(max_height) - double(min_height)) / 32767.0; }
  std::size_t vertexCount() const { return u.size(); }
};

// The mesh's heights (metres) at the points of a regular (cells + 1)^2 grid over the tile, index
// j * (cells + 1) + i with i eastwards and j northwards from the south-west corner: each point
// interpolated linearly in the triangle that holds it (u/v as the tile stores them), the first
// counter-clockwise one where several overlap (a mesh simplified in 3D can fold over itself in u/v
// on steep ground; folded, clockwise triangles answer only where no other does); NaN at a point no
// triangle holds (never for a tile that covers its square, as every quantized-mesh tile must).
std::vector<double> meshHeightsOnGrid(const DecodedMesh& mesh, int cells);

// Nothing when the bytes are not a well-formed tile (truncated, trailing bytes, index out of range).
std::optional<DecodedMesh> decodeQuantizedMesh(const std::string& bytes, std::string* why = nullptr);

}  // namespace globe
