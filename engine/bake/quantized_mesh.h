#pragma once
// quantized-mesh-1.0, the terrain tile format of Cesium clients [Cesium 2014]: a header (ECEF centre,
// height range, bounding sphere, horizon-occlusion point), vertices as u, v, height in [0, 32767]
// (zig-zag, delta encoded), triangles as high-water-mark encoded indices, the vertices on each of the
// four edges, and the oct-encoded vertex-normals extension. Little-endian throughout.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace globe {

inline constexpr std::uint16_t kQuantizedMax = 32767;
inline constexpr std::uint8_t kOctVertexNormalsExtension = 1;

struct QuantizedMeshHeader {
  glm::dvec3 center_m{0.0};  // ECEF (planet-fixed) metres
  float min_height_m = 0.0f;
  float max_height_m = 0.0f;
  glm::dvec3 sphere_center_m{0.0};
  double sphere_radius_m = 0.0;
  glm::dvec3 horizon_occlusion_point{0.0};  // scaled space (positions / radius)
};

struct QuantizedMeshTile {
  QuantizedMeshHeader header;
  std::vector<std::uint16_t> u, v, height;           // per vertex, [0, kQuantizedMax]
  std::vector<std::uint32_t> indices;                // triangles, counter-clockwise seen from above; vertices
                                                     // numbered in order of first use (high-water mark)
  std::array<std::vector<std::uint32_t>, 4> edges;   // west, south, east, north vertex indices
  std::vector<std::array<std::uint8_t, 2>> normals;  // oct-encoded, per vertex
};

// The tile's bytes. The indices must be numbered in order of first use (asserted).
std::string encodeQuantizedMesh(const QuantizedMeshTile& tile);

// Oct encoding of a unit vector into two bytes [Cigolle 2014, §3.1].
std::array<std::uint8_t, 2> octEncode(const glm::dvec3& unit);

}  // namespace globe
