#pragma once
// Geometry shared by the rendering tests: rays through pixel positions of a test view.
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "planet/camera/camera.h"
#include "planet/geometry/angles.h"

namespace globe::testing {

// Unit ray through pixel position (x, y) of a width x height view (pixels, y down; integer
// coordinates are pixel corners, + 0.5 the centres).
inline glm::dvec3 pixelPositionRay(const Camera& camera, double x, double y, uint32_t width, uint32_t height) {
  const double tanY = std::tan(camera.verticalFov_rad * 0.5), tanX = tanY * camera.aspect;
  const double nx = x / width * 2.0 - 1.0, ny = y / height * 2.0 - 1.0;
  return glm::normalize(camera.forward + nx * tanX * camera.right - ny * tanY * camera.up);
}

}  // namespace globe::testing
