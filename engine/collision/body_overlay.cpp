#include "engine/collision/body_overlay.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace globe {

namespace {

glm::vec3 shapeColour(BodyShape shape) {
  switch (shape) {
    case BodyShape::kSphere:
      return {0.9f, 0.1f, 0.1f};
    case BodyShape::kBox:
      return {0.95f, 0.85f, 0.1f};
    case BodyShape::kCapsule:
      return {0.1f, 0.85f, 0.9f};
  }
  return {1.0f, 1.0f, 1.0f};
}

}  // namespace

uint32_t drawBodies(ImageRgba& image, const Camera& camera, const PhysicsWorld& world) {
  const double focal_px = 0.5 * double(image.height) / std::tan(0.5 * camera.verticalFov_rad);
  uint32_t visible = 0;
  for (uint32_t id = 0; id < world.bodyCount(); ++id) {
    const glm::dvec3 centre = world.state(id).position_m;
    const glm::dvec3 light = glm::normalize(centre);  // lit from straight above
    bool any = false;
    for (const glm::dvec3& p : world.surfacePoints(id)) {
      const glm::dvec3 rel = p - camera.position_m;
      const double depth = glm::dot(rel, camera.forward);
      if (depth <= camera.near_m) continue;
      const double x = 0.5 * image.width + focal_px * glm::dot(rel, camera.right) / depth;
      const double y = 0.5 * image.height - focal_px * glm::dot(rel, camera.up) / depth;
      const double radius_px = std::max(1.5, 0.35 * world.spec(id).size_m * focal_px / depth);
      const float shade = float(0.35 + 0.65 * std::max(0.0, glm::dot(glm::normalize(p - centre), light)));
      const glm::vec3 colour = shapeColour(world.spec(id).shape) * shade;
      const double distance = glm::length(rel);
      for (int py = int(y - radius_px); py <= int(y + radius_px); ++py) {
        for (int px = int(x - radius_px); px <= int(x + radius_px); ++px) {
          if (px < 0 || py < 0 || px >= int(image.width) || py >= int(image.height)) continue;
          if ((px - x) * (px - x) + (py - y) * (py - y) > radius_px * radius_px) continue;
          const size_t k = size_t(py) * image.width + size_t(px);
          if (!image.z.empty() && image.z[k] > 0.0f && double(image.z[k]) < distance - world.spec(id).size_m) continue;
          image.rgba[4 * k] = colour.x;
          image.rgba[4 * k + 1] = colour.y;
          image.rgba[4 * k + 2] = colour.z;
          any = true;
        }
      }
    }
    visible += any ? 1u : 0u;
  }
  return visible;
}

}  // namespace globe
