#include "engine/viewer/viewer_bodies.h"

#include "planet/analysis/terrain_queries.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace globe {

ViewerBodies::ViewerBodies(vk::Device& device, const ElevationModel& model, double surfaceGravity_m_s2, uint32_t cells)
    : model_(model), source_(device, model, cells, 16) {
  SimulationSettings settings;
  settings.level = 14;
  settings.interestRadius_m = 16.0;
  settings.physics.surfaceGravity_m_s2 = surfaceGravity_m_s2;
  settings.pool.maxInFlight = 16;
  simulation_ = std::make_unique<PhysicsSimulation>(model, source_, settings);
}

bool ViewerBodies::dropWhereLooking(const Camera& camera) {
  const auto hit = TerrainQueries(model_).rayExact(camera.position_m, camera.forward, 1.0e5);
  if (!hit) return false;
  const glm::dvec3 ground = camera.position_m + camera.forward * *hit;
  BodySpec spec;
  constexpr BodyShape kTurns[3] = {BodyShape::kSphere, BodyShape::kBox, BodyShape::kCapsule};
  spec.shape = kTurns[count() % 3];
  spec.size_m = 1.0;
  spec.position_m = ground + glm::normalize(ground) * 3.0;
  simulation_->addBody(spec);
  return true;
}

void ViewerBodies::advance(double dt_s) {
  const double step = simulation_->settings().physics.step_s;
  pending_s_ = std::min(pending_s_ + dt_s, 8.0 * step);
  while (pending_s_ >= step) {
    simulation_->step();
    pending_s_ -= step;
  }
}

std::vector<OverlayDisc> ViewerBodies::discs(const Camera& camera, double width_px, double height_px) const {
  std::vector<OverlayDisc> out;
  const double focal_px = 0.5 * height_px / std::tan(0.5 * camera.verticalFov_rad);
  const PhysicsWorld& world = simulation_->world();
  for (uint32_t id = 0; id < world.bodyCount(); ++id) {
    const glm::dvec3 rel = world.state(id).position_m - camera.position_m;
    const double depth = glm::dot(rel, camera.forward);
    if (depth <= camera.near_m) continue;
    OverlayDisc disc;
    disc.x_px = float(0.5 * width_px + focal_px * glm::dot(rel, camera.right) / depth);
    disc.y_px = float(0.5 * height_px - focal_px * glm::dot(rel, camera.up) / depth);
    disc.radius_px = float(std::max(2.0, 0.5 * world.spec(id).size_m * focal_px / depth));
    disc.shape = uint8_t(world.spec(id).shape);
    out.push_back(disc);
  }
  return out;
}

}  // namespace globe
