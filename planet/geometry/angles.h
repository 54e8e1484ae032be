#pragma once
// The angle between two directions, accurate near 0 and pi (unlike acos of the dot product).
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace globe {

// Radians in [0, pi]; a and b need not be unit length.
inline double angleBetween_rad(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace globe
