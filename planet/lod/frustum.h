#pragma once
// View frustum culling [Frasson 2018, §3.2.2]: conservative — a node is culled only when all 8
// corners of its bounds are outside one plane; a node wholly inside lets its children skip the test.
#include <array>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "planet/core/error.h"
#include "planet/geometry/node_bounds.h"

namespace globe {

enum class Containment { kOutside, kIntersecting, kInside };

class Frustum {
 public:
  // From a view-projection matrix (GLM column-major, planet-fixed metres -> Vulkan clip space with
  // 0 <= z <= w, either depth direction). Degenerate planes (an infinite far plane) are dropped.
  // Non-finite entries are an Error.
  static Result<Frustum> fromViewProjection(const glm::dmat4& viewProjection);
  // From up to 6 planes (xyz normal pointing into the frustum, w offset: inside when dot + w >= 0),
  // normalised here. Non-finite or zero normals are an Error.
  static Result<Frustum> fromPlanes(std::span<const glm::dvec4> inwardPlanes);

  Containment classify(const NodeBounds& bounds) const;
  bool contains(const glm::dvec3& point) const;
  std::span<const glm::dvec4> planes() const { return {planes_.data(), static_cast<size_t>(count_)}; }

 private:
  std::array<glm::dvec4, 6> planes_{};  // inward unit normals
  int count_ = 0;
};

}  // namespace globe
