#pragma once
// The tests' own quantized-mesh-1.0 reader, written from the format's description independently of
// the encoder (engine/bake/quantized_mesh.cpp) so that the two check each other: zig-zag deltas,
// high-water-mark indices, 16/32-bit indices and their alignment, edges, extensions.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace globe::testing {

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
};

// Nothing when the bytes are not a well-formed tile (truncated, trailing bytes, index out of range).
std::optional<DecodedMesh> decodeQuantizedMesh(const std::string& bytes, std::string* why = nullptr);

}  // namespace globe::testing
