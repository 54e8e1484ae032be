#pragma once
// Rigid bodies on the collision meshes, through Bullet's double-precision build
// (BT_USE_DOUBLE_PRECISION; Bullet stays behind this interface, so no other file depends on how it
// was compiled). Everything is in planet-centred, planet-fixed metres: doubles carry 6e6 m with
// nanometre steps, so no floating origin is needed. Each collision mesh is one static concave
// shape indexed by its vertex grid (grid_mesh_shape.h) whose transform is the payload's node centre
// in the node's tangent frame [Frasson 2018, §3.4].
//
// Gravity is radial: g(r) = surfaceGravity · (radius / r)^2 towards the centre, set per body before
// every step. Steps are fixed (PhysicsSettings::step_s, one Bullet substep each), so a run is
// deterministic for the same bodies and the same meshes arriving at the same steps.
#include "planet/core/parallel_for.h"
#include "planet/physics/collision_mesh_pool.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace globe {

enum class BodyShape : uint8_t { kSphere, kBox, kCapsule };
std::string_view bodyShapeName(BodyShape shape);  // "sphere", "box", "capsule"

struct BodySpec {
  BodyShape shape = BodyShape::kSphere;
  // Sphere: diameter. Box: edge of a cube. Capsule: diameter (its total length is twice that).
  double size_m = 1.0;
  glm::dvec3 position_m{0.0};  // centre of mass, planet-centred
  glm::dvec3 velocity_m_s{0.0};
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
  double density_kg_m3 = 1000.0;
};

struct PhysicsSettings {
  double planetRadius_m = 6371000.0;  // the equatorial radius on an ellipsoid
  double surfaceGravity_m_s2 = 9.81;  // at planetRadius_m
  // Of the planet's ellipsoid: gravity pulls along its normal (the plumb line), not at the centre,
  // so a body at rest on level ground stays there; 0: a sphere, radial.
  double flattening = 0.0;
  double step_s = 1.0 / 120.0;
  // Bullet multiplies the two objects' coefficients; the terrain's are 1, so these are the pair's.
  double friction = 1.0;  // holds a box on slopes up to 45 degrees
  // Rolling resistance of spheres and capsules (dimensionless, torque / (weight · radius)), so they
  // stop on slopes like boxes do. Bullet caps a contact's rolling-friction impulse at the
  // coefficient itself, so the body's coefficient is set to this times radius · m · g · step.
  double rollingResistance = 1.0;
  double linearDamping = 0.05;  // per second: air drag, small
  double angularDamping = 0.3;  // per second: lets rolling and tumbling die out
  double restitution = 0.1;
  double sleepLinear_m_s = 0.04;  // below both for Bullet's deactivation time (2 s) -> asleep
  double sleepAngular_rad_s = 0.1;
  double meshMargin_m = 0.0;  // collision margin of the terrain triangles
  // Independent Bullet worlds (planet/physics/body_groups.h): bodies that may meet share one. A
  // fixed number, so a run's result does not depend on the machine; stepped on up to `threads`.
  uint32_t worlds = 2;
  unsigned threads = 2;
};

struct BodyState {
  glm::dvec3 position_m{0.0};
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 velocity_m_s{0.0};
  bool sleeping = false;
};

class PhysicsWorld final : public CollisionMeshListener {
 public:
  explicit PhysicsWorld(const PhysicsSettings& settings);
  ~PhysicsWorld() override;
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  uint32_t addBody(const BodySpec& spec);  // ids count from 0
  size_t bodyCount() const;
  const BodySpec& spec(uint32_t id) const;
  BodyState state(uint32_t id) const;
  // Radius of the sphere around the centre of mass that holds the body.
  double boundingRadius(uint32_t id) const;
  // Points on the body's surface (world metres): corners, edge and face centres of a box, a grid
  // of a sphere's or capsule's surface. The lowest of them above the terrain is the body's clearance.
  std::vector<glm::dvec3> surfacePoints(uint32_t id) const;

  // One fixed step: gravity (along the ellipsoid's normal, radial on a sphere), integration,
  // collisions, then the contacts per body.
  void step();
  // Collision meshes (nodes) the body touched at the last step.
  std::span<const NodeId> contactNodes(uint32_t id) const;

  // Nearest hit of the ray from `origin_m` along unit `direction` within maxDistance_m on the
  // collision meshes (bodies ignored); nullopt when none.
  std::optional<double> rayCastMeshes(const glm::dvec3& origin_m, const glm::dvec3& direction,
                                      double maxDistance_m) const;

  void meshResident(const CollisionMesh& mesh) override;
  void meshEvicted(const NodeId& node) override;
  size_t meshCount() const;
  const PhysicsSettings& settings() const { return settings_; }
  // The physics threads (settings().threads, persistent): the worlds step on them, and the
  // simulation runs its per-body loops on them.
  ThreadTeam& threads() const;

 private:
  struct Impl;
  PhysicsSettings settings_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace globe
