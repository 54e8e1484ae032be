#include "engine/bake/quantized_mesh.h"

#include <cassert>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace globe {

namespace {

// Appends the little-endian bytes of a trivially copyable value (x86-64 and ARM64 are little-endian).
template <class T>
void put(std::string& out, T value) {
  static_assert(std::is_trivially_copyable_v<T>);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

void putVec(std::string& out, const glm::dvec3& v) {
  put(out, v.x);
  put(out, v.y);
  put(out, v.z);
}

std::uint16_t zigZag(int value) {
  return static_cast<std::uint16_t>((static_cast<unsigned>(value) << 1) ^ static_cast<unsigned>(value >> 31));
}

void putDeltas(std::string& out, const std::vector<std::uint16_t>& values) {
  int previous = 0;
  for (std::uint16_t value : values) {
    put(out, zigZag(int(value) - previous));
    previous = value;
  }
}

void putIndex(std::string& out, std::uint32_t index, bool wide) {
  if (wide) {
    put(out, index);
  } else {
    put(out, static_cast<std::uint16_t>(index));
  }
}

void putHeader(std::string& out, const QuantizedMeshHeader& h) {
  putVec(out, h.center_m);
  put(out, h.min_height_m);
  put(out, h.max_height_m);
  putVec(out, h.sphere_center_m);
  put(out, h.sphere_radius_m);
  putVec(out, h.horizon_occlusion_point);
}

}  // namespace

std::string encodeQuantizedMesh(const QuantizedMeshTile& tile) {
  const auto vertexCount = static_cast<std::uint32_t>(tile.u.size());
  assert(tile.v.size() == vertexCount && tile.height.size() == vertexCount && tile.normals.size() == vertexCount);
  const bool wide = vertexCount > 65536;
  std::string out;
  putHeader(out, tile.header);
  put(out, vertexCount);
  putDeltas(out, tile.u);
  putDeltas(out, tile.v);
  putDeltas(out, tile.height);
  while (out.size() % (wide ? 4 : 2) != 0) out.push_back('\0');
  put(out, static_cast<std::uint32_t>(tile.indices.size() / 3));
  std::uint32_t highest = 0;
  for (std::uint32_t index : tile.indices) {
    assert(index <= highest);
    putIndex(out, highest - index, wide);
    if (index == highest) ++highest;
  }
  for (const auto& edge : tile.edges) {
    put(out, static_cast<std::uint32_t>(edge.size()));
    for (std::uint32_t index : edge) putIndex(out, index, wide);
  }
  put(out, kOctVertexNormalsExtension);
  put(out, static_cast<std::uint32_t>(vertexCount * 2));
  for (const auto& n : tile.normals) out.append(reinterpret_cast<const char*>(n.data()), 2);
  return out;
}

std::array<std::uint8_t, 2> octEncode(const glm::dvec3& unit) {
  const double l1 = std::abs(unit.x) + std::abs(unit.y) + std::abs(unit.z);
  double x = unit.x / l1;
  double y = unit.y / l1;
  if (unit.z < 0.0) {  // fold the lower hemisphere over the diagonals
    const double fx = (1.0 - std::abs(y)) * (x >= 0.0 ? 1.0 : -1.0);
    const double fy = (1.0 - std::abs(x)) * (y >= 0.0 ? 1.0 : -1.0);
    x = fx;
    y = fy;
  }
  auto toByte = [](double s) { return static_cast<std::uint8_t>(std::lround((s * 0.5 + 0.5) * 255.0)); };
  return {toByte(x), toByte(y)};
}

}  // namespace globe
