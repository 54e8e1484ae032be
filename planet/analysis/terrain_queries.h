#pragma once
// Height and ray queries against the terrain, for cameras and bodies that must never end up under
// the ground (docs/physics.md):
//  - exact: the CPU double model (ElevationModel), the ground truth;
//  - as drawn: the payload mesh at a level (drawnSurfaceRadius), which misses the relief finer than
//    its samples and so lies above or below the exact surface by up to that relief;
//  - rays against the exact surface in double (SurfaceRayCaster); rays against the collision
//    meshes are PhysicsWorld::rayCastMeshes (planet/physics).
#include "planet/analysis/surface_ray.h"
#include "planet/model/elevation_model.h"

#include <glm/vec3.hpp>
#include <optional>

namespace globe {

class TerrainQueries {
 public:
  // `model` must outlive the queries.
  explicit TerrainQueries(const ElevationModel& model);

  // Height above radius_m (metres) at a unit direction: exact, and as drawn by nodes at `level`
  // with `cells` cells per side (unmorphed).
  double exactHeight_m(const glm::dvec3& unitDirection) const;
  double drawnHeight_m(const glm::dvec3& unitDirection, int level, uint32_t cells) const;
  // The radius a camera must stay above: the higher of the exact surface and the mesh drawn at
  // `level` (a camera under the drawn mesh sees through it, one under the exact one is underground).
  double cameraFloorRadius(const glm::dvec3& unitDirection, int level, uint32_t cells) const;

  // First hit of the ray (unit `direction`) with the exact surface within maxDistance_m.
  std::optional<double> rayExact(const glm::dvec3& origin_m, const glm::dvec3& direction, double maxDistance_m) const;

  // Moves a camera from `from_m` (above the surface) towards `to_m` without ever passing below the
  // exact surface, however long the move: the segment is ray cast, the camera stops `clearance_m`
  // short of a hit, and the result is lifted radially to cameraFloorRadius + clearance_m.
  glm::dvec3 guardedMove(const glm::dvec3& from_m, const glm::dvec3& to_m, double clearance_m, int level,
                         uint32_t cells) const;

  const ElevationModel& model() const { return model_; }

 private:
  const ElevationModel& model_;
  SurfaceRayCaster rays_;
};

}  // namespace globe
