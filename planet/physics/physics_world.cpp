#include "planet/physics/physics_world.h"

#include "planet/physics/body_groups.h"
#include "planet/physics/grid_mesh_shape.h"

#include <btBulletCollisionCommon.h>
#include <btBulletDynamicsCommon.h>

#include <glm/geometric.hpp>

#include <cassert>
#include <cmath>
#include <unordered_map>

static_assert(sizeof(btScalar) == sizeof(double), "globe::physics needs Bullet's double-precision build");

namespace globe {

namespace {

btVector3 toBt(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
glm::dvec3 fromBt(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
btQuaternion toBt(const glm::dquat& q) { return {q.x, q.y, q.z, q.w}; }
glm::dquat fromBt(const btQuaternion& q) { return {q.w(), q.x(), q.y(), q.z()}; }

constexpr double kPi = 3.14159265358979323846;

// Bullet clamps combined rolling friction to 10 (an angular impulse per step, see addBody), which
// stops nothing heavier than a few hundred kilograms; the same combination without the clamp.
btScalar combinedRollingFriction(const btCollisionObject* a, const btCollisionObject* b) {
  return a->getRollingFriction() * b->getFriction() + b->getRollingFriction() * a->getFriction();
}

// A static terrain mesh: its vertices turned into the node's tangent frame (z up at the node
// centre), indexed by its grid (planet/physics/grid_mesh_shape.h), and its object at the node
// centre, one per world. In the tangent frame the mesh's box is a flat slab around the terrain, so
// a body above the ground misses it at once (meshNearCallback); in planet-aligned axes a tilted
// patch's box is a cube full of empty air.
// A mesh's object in one world: the node and the mesh's box in its tangent frame sit beside the
// transform, so the near callback's test reads one object (it runs for every body-mesh pair).
struct MeshObject final : btCollisionObject {
  NodeId node;
  btVector3 localMin, localMax;
};

struct StaticMesh {
  std::unique_ptr<GridMeshShape> shape;
  std::vector<std::unique_ptr<MeshObject>> objects;  // one per world, sharing the shape
};

// Columns east, north, up of the tangent frame at `centre_m` (any east where the up is a pole).
btMatrix3x3 tangentFrame(const glm::dvec3& centre_m) {
  const glm::dvec3 up = glm::normalize(centre_m);
  const glm::dvec3 pole = std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 east = glm::normalize(glm::cross(pole, up));
  const glm::dvec3 north = glm::cross(up, east);
  return {east.x, north.x, up.x, east.y, north.y, up.y, east.z, north.z, up.z};
}

// Bullet's broadphase pairs a body with every mesh whose planet-aligned box holds it, and a tilted
// 250 m patch's box holds the air above it and its neighbours' ground: ~1.5 pairs a body, each a
// narrowphase. This skips the narrowphase of a pair whose body (a sphere around its broadphase box,
// which covers its motion in the step and the contact threshold) misses the mesh's box in the
// mesh's tangent frame, where that box is a thin slab; its contacts were all beyond breaking
// distance, so they are dropped as Bullet's refresh would have dropped them.
void meshNearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher, const btDispatcherInfo& info) {
  btBroadphaseProxy* meshProxy = pair.m_pProxy0;
  btBroadphaseProxy* bodyProxy = pair.m_pProxy1;
  // Meshes are the static filter group (meshResident), read from the proxy without the object.
  auto isMesh = [](const btBroadphaseProxy* p) {
    return (p->m_collisionFilterGroup & btBroadphaseProxy::StaticFilter) != 0;
  };
  if (!isMesh(meshProxy)) std::swap(meshProxy, bodyProxy);
  if (isMesh(meshProxy) && !isMesh(bodyProxy)) {
    const auto* object = static_cast<const MeshObject*>(meshProxy->m_clientObject);
    constexpr double kSlack_m = 0.1;
    const btVector3 centre = 0.5 * (bodyProxy->m_aabbMin + bodyProxy->m_aabbMax);
    const double radius = 0.5 * (bodyProxy->m_aabbMax - bodyProxy->m_aabbMin).length() + kSlack_m;
    const btVector3 local = object->getWorldTransform().invXform(centre);
    bool apart = false;
    for (int axis = 0; axis < 3; ++axis)
      apart |= local[axis] + radius < object->localMin[axis] || local[axis] - radius > object->localMax[axis];
    if (apart) {
      if (pair.m_algorithm) {
        btManifoldArray manifolds;
        pair.m_algorithm->getAllContactManifolds(manifolds);
        for (int m = 0; m < manifolds.size(); ++m) manifolds[m]->clearManifold();
      }
      return;
    }
  }
  btCollisionDispatcher::defaultNearCallback(pair, dispatcher, info);
}

struct Body {
  BodySpec spec;
  std::unique_ptr<btCollisionShape> shape;
  std::unique_ptr<btRigidBody> rigid;
  std::vector<NodeId> contacts;
  double boundingRadius_m = 0.0;
  uint32_t world = 0;  // which Shard holds it
};

// One independent Bullet world: its own pools (in the configuration), broadphase and solver, so
// shards step on different threads without sharing anything but the read-only mesh shapes.
struct Shard {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::vector<uint32_t> bodies;  // ids, ascending
};

// Groups are formed again every this many steps; a body's reach covers its motion over twice that.
constexpr uint64_t kRegroupSteps = 4;
constexpr double kReachSlack_m = 1.0;

}  // namespace

struct PhysicsWorld::Impl {
  explicit Impl(unsigned threads) : team(threads) {}
  ThreadTeam team;
  std::vector<std::unique_ptr<Shard>> shards;
  std::vector<Body> bodies;
  std::unordered_map<uint64_t, std::unique_ptr<StaticMesh>> meshes;
  uint64_t steps = 0;

  void regroup(double step_s);
  void stepShard(Shard& shard, const PhysicsSettings& settings);
};

std::string_view bodyShapeName(BodyShape shape) {
  switch (shape) {
    case BodyShape::kSphere:
      return "sphere";
    case BodyShape::kBox:
      return "box";
    case BodyShape::kCapsule:
      return "capsule";
  }
  return "sphere";
}

PhysicsWorld::PhysicsWorld(const PhysicsSettings& settings)
    : settings_(settings), impl_(std::make_unique<Impl>(settings.threads)) {
  for (uint32_t w = 0; w < std::max(settings_.worlds, 1u); ++w) {
    auto shard = std::make_unique<Shard>();
    shard->world.setGravity(btVector3(0, 0, 0));  // along the local vertical, per body (step())
    // Terrain meshes never move: only active bodies' bounds are updated each step (Bullet's default
    // recomputes every object's, ~10 % of a step with 1 600 meshes resident).
    shard->world.setForceUpdateAllAabbs(false);
    shard->dispatcher.setNearCallback(&meshNearCallback);
    // Bodies rest on static ground, one contact manifold each and rarely a stack: half of Bullet's
    // default 10 solver iterations hold them (the rest and fall-through tests).
    shard->world.getSolverInfo().m_numIterations = 5;
    impl_->shards.push_back(std::move(shard));
  }
  gCalculateCombinedRollingFrictionCallback = &combinedRollingFriction;
  gCalculateCombinedSpinningFrictionCallback = &combinedRollingFriction;
}

PhysicsWorld::~PhysicsWorld() {
  for (Body& b : impl_->bodies) impl_->shards[b.world]->world.removeRigidBody(b.rigid.get());
  for (auto& [key, mesh] : impl_->meshes)
    for (size_t w = 0; w < mesh->objects.size(); ++w)
      impl_->shards[w]->world.removeCollisionObject(mesh->objects[w].get());
}

uint32_t PhysicsWorld::addBody(const BodySpec& spec) {
  Body body;
  body.spec = spec;
  const double half = 0.5 * spec.size_m;
  double volume_m3 = 0.0;
  switch (spec.shape) {
    case BodyShape::kSphere:
      body.shape = std::make_unique<btSphereShape>(half);
      body.boundingRadius_m = half;
      volume_m3 = 4.0 / 3.0 * kPi * half * half * half;
      break;
    case BodyShape::kBox:
      body.shape = std::make_unique<btBoxShape>(btVector3(half, half, half));
      body.boundingRadius_m = half * std::sqrt(3.0);
      volume_m3 = spec.size_m * spec.size_m * spec.size_m;
      break;
    case BodyShape::kCapsule:
      body.shape = std::make_unique<btCapsuleShape>(half, spec.size_m);  // radius, cylinder height
      body.boundingRadius_m = half + 0.5 * spec.size_m;
      volume_m3 = kPi * half * half * (spec.size_m + 4.0 / 3.0 * half);
      break;
  }
  const double mass = spec.density_kg_m3 * volume_m3;
  btVector3 inertia(0, 0, 0);
  body.shape->calculateLocalInertia(mass, inertia);
  // No motion state: state() reads the body's transform, and Bullet then skips interpolating and
  // copying every active body's transform after each step.
  btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, body.shape.get(), inertia);
  info.m_startWorldTransform = btTransform(toBt(spec.orientation), toBt(spec.position_m));
  info.m_friction = settings_.friction;
  info.m_restitution = settings_.restitution;
  info.m_linearSleepingThreshold = settings_.sleepLinear_m_s;
  info.m_angularSleepingThreshold = settings_.sleepAngular_rad_s;
  info.m_linearDamping = settings_.linearDamping;
  info.m_angularDamping = settings_.angularDamping;
  if (spec.shape != BodyShape::kBox) {
    const double r = std::max(glm::length(spec.position_m), 1.0);
    const double g = settings_.surfaceGravity_m_s2 * (settings_.planetRadius_m / r) * (settings_.planetRadius_m / r);
    info.m_rollingFriction = settings_.rollingResistance * half * mass * g * settings_.step_s;
    info.m_spinningFriction = info.m_rollingFriction;
  }
  body.rigid = std::make_unique<btRigidBody>(info);
  body.rigid->setLinearVelocity(toBt(spec.velocity_m_s));
  // A sphere's and a cube's inertia is isotropic: no gyroscopic torque to integrate.
  if (spec.shape != BodyShape::kCapsule)
    body.rigid->setFlags(body.rigid->getFlags() & ~BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
  // Continuous collision: a body moving more than a quarter of its size in a step is swept, so a
  // 50 m/s impact cannot tunnel through a one-sided terrain triangle.
  body.rigid->setCcdMotionThreshold(0.25 * spec.size_m);
  body.rigid->setCcdSweptSphereRadius(0.4 * spec.size_m);
  const uint32_t id = uint32_t(impl_->bodies.size());
  body.rigid->setUserIndex(int(id));
  body.world = id % uint32_t(impl_->shards.size());  // assignWorlds' start; regroup() moves it if needed
  impl_->shards[body.world]->world.addRigidBody(body.rigid.get());
  impl_->shards[body.world]->bodies.push_back(id);
  impl_->bodies.push_back(std::move(body));
  return id;
}

size_t PhysicsWorld::bodyCount() const { return impl_->bodies.size(); }
const BodySpec& PhysicsWorld::spec(uint32_t id) const { return impl_->bodies[id].spec; }
double PhysicsWorld::boundingRadius(uint32_t id) const { return impl_->bodies[id].boundingRadius_m; }

BodyState PhysicsWorld::state(uint32_t id) const {
  const btRigidBody& rigid = *impl_->bodies[id].rigid;
  const btTransform& t = rigid.getWorldTransform();
  return {fromBt(t.getOrigin()), fromBt(t.getRotation()), fromBt(rigid.getLinearVelocity()),
          rigid.getActivationState() == ISLAND_SLEEPING};
}

std::vector<glm::dvec3> PhysicsWorld::surfacePoints(uint32_t id) const {
  const Body& body = impl_->bodies[id];
  const btTransform& t = body.rigid->getWorldTransform();
  const double half = 0.5 * body.spec.size_m;
  std::vector<glm::dvec3> points;
  auto add = [&](double x, double y, double z) { points.push_back(fromBt(t * btVector3(x, y, z))); };
  if (body.spec.shape == BodyShape::kBox) {
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z)
          if (x || y || z) add(half * x, half * y, half * z);
    return points;
  }
  // Sphere (or the capsule's two end spheres, Bullet's capsule axis is y): a latitude-longitude grid.
  const double ends = body.spec.shape == BodyShape::kCapsule ? 0.5 * body.spec.size_m : 0.0;
  for (double offset : {-ends, ends}) {
    for (int a = 0; a <= 8; ++a) {
      const double polar = kPi * a / 8.0;
      for (int b = 0; b < 16; ++b) {
        const double azimuth = 2.0 * kPi * b / 16.0;
        add(half * std::sin(polar) * std::cos(azimuth), offset + half * std::cos(polar),
            half * std::sin(polar) * std::sin(azimuth));
      }
    }
    if (ends == 0.0) break;
  }
  // The capsule's cylinder: rings between the end spheres.
  for (int k = 1; ends > 0.0 && k < 8; ++k) {
    const double y = -ends + 2.0 * ends * k / 8.0;
    for (int b = 0; b < 16; ++b) {
      const double azimuth = 2.0 * kPi * b / 16.0;
      add(half * std::cos(azimuth), y, half * std::sin(azimuth));
    }
  }
  return points;
}

// Bodies that may meet share a world (planet/physics/body_groups.h); a body whose group moved is
// taken out of its old world and added to the new one, in id order.
void PhysicsWorld::Impl::regroup(double step_s) {
  std::vector<BodyReach> reach(bodies.size());
  std::vector<uint32_t> previous(bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) {
    const btRigidBody& rigid = *bodies[i].rigid;
    const double travel_m = rigid.getLinearVelocity().length() * step_s * double(2 * kRegroupSteps);
    reach[i] = {fromBt(rigid.getCenterOfMassPosition()), bodies[i].boundingRadius_m + travel_m + kReachSlack_m};
    previous[i] = bodies[i].world;
  }
  const std::vector<uint32_t> worlds = assignWorlds(groupBodies(reach), previous, uint32_t(shards.size()));
  bool moved = false;
  for (uint32_t i = 0; i < bodies.size(); ++i) {
    Body& b = bodies[i];
    if (worlds[i] == b.world) continue;
    const btVector3 gravity = b.rigid->getGravity();  // addRigidBody sets the world's (zero)
    shards[b.world]->world.removeRigidBody(b.rigid.get());
    b.world = worlds[i];
    shards[b.world]->world.addRigidBody(b.rigid.get());
    b.rigid->setGravity(gravity);
    moved = true;
  }
  if (!moved) return;
  for (auto& shard : shards) shard->bodies.clear();
  for (uint32_t i = 0; i < bodies.size(); ++i) shards[bodies[i].world]->bodies.push_back(i);
}

void PhysicsWorld::Impl::stepShard(Shard& shard, const PhysicsSettings& settings) {
  const double g0 = settings.surfaceGravity_m_s2, r0 = settings.planetRadius_m;
  // The ellipsoid's gradient (x, y, z (a/b)^2): its normal at the surface, and within h f / a of it
  // at height h (bodies are metres above the ground).
  const double polarStretch = 1.0 / ((1.0 - settings.flattening) * (1.0 - settings.flattening));
  for (uint32_t id : shard.bodies) {
    Body& b = bodies[id];
    b.contacts.clear();
    if (!b.rigid->isActive()) continue;
    const glm::dvec3 p = fromBt(b.rigid->getCenterOfMassPosition());
    const double r = glm::length(p);
    const double g = g0 * (r0 / r) * (r0 / r);
    // On a sphere the radial form, so spherical runs stay bit for bit what they were.
    b.rigid->setGravity(toBt(
        settings.flattening == 0.0 ? p * (-g / r) : -glm::normalize(glm::dvec3(p.x, p.y, p.z * polarStretch)) * g));
  }
  shard.world.stepSimulation(settings.step_s, 0);  // 0 substeps: exactly one step of step_s
  const int manifolds = shard.dispatcher.getNumManifolds();
  for (int m = 0; m < manifolds; ++m) {
    const btPersistentManifold* manifold = shard.dispatcher.getManifoldByIndexInternal(m);
    if (manifold->getNumContacts() == 0) continue;
    const btCollisionObject* a = manifold->getBody0();
    const btCollisionObject* b = manifold->getBody1();
    if (a->getUserIndex() < 0) std::swap(a, b);
    if (a->getUserIndex() < 0 || b->getUserIndex() >= 0) continue;  // body-body or mesh-mesh
    bodies[size_t(a->getUserIndex())].contacts.push_back(static_cast<const MeshObject*>(b)->node);
  }
}

void PhysicsWorld::step() {
  if (impl_->shards.size() > 1 && impl_->steps % kRegroupSteps == 0) impl_->regroup(settings_.step_s);
  // Shards share no mutable state: each writes only its own bodies' contacts.
  impl_->team.run(impl_->shards.size(), 1, [&](size_t begin, size_t end) {
    for (size_t w = begin; w < end; ++w) impl_->stepShard(*impl_->shards[w], settings_);
  });
  ++impl_->steps;
}

std::span<const NodeId> PhysicsWorld::contactNodes(uint32_t id) const { return impl_->bodies[id].contacts; }

std::optional<double> PhysicsWorld::rayCastMeshes(const glm::dvec3& origin_m, const glm::dvec3& direction,
                                                  double maxDistance_m) const {
  const btVector3 from = toBt(origin_m), to = toBt(origin_m + direction * maxDistance_m);
  btCollisionWorld::ClosestRayResultCallback hit(from, to);
  hit.m_collisionFilterMask = btBroadphaseProxy::StaticFilter;
  impl_->shards[0]->world.rayTest(from, to, hit);  // every world holds every mesh
  if (!hit.hasHit()) return std::nullopt;
  return hit.m_closestHitFraction * maxDistance_m;
}

void PhysicsWorld::meshResident(const CollisionMesh& mesh) {
  auto s = std::make_unique<StaticMesh>();
  const btMatrix3x3 frame = tangentFrame(mesh.centre_m);
  std::vector<double> local_m(mesh.vertices_m.size());
  for (size_t k = 0; k + 2 < mesh.vertices_m.size(); k += 3) {
    const btVector3 local = btVector3(mesh.vertices_m[k], mesh.vertices_m[k + 1], mesh.vertices_m[k + 2]) * frame;
    local_m[k] = local.x(), local_m[k + 1] = local.y(), local_m[k + 2] = local.z();
  }
  s->shape = std::make_unique<GridMeshShape>(mesh.cells, std::move(local_m));
  s->shape->setMargin(settings_.meshMargin_m);
  for (auto& shard : impl_->shards) {
    auto object = std::make_unique<MeshObject>();
    object->node = mesh.node;
    object->localMin = s->shape->localMin();
    object->localMax = s->shape->localMax();
    object->setCollisionShape(s->shape.get());
    object->setWorldTransform(btTransform(frame, toBt(mesh.centre_m)));
    object->setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
    object->setFriction(1.0);
    object->setRollingFriction(0.0);  // the pair's rolling friction is the body's (see addBody)
    object->setRestitution(1.0);
    object->setUserIndex(-1);
    shard->world.addCollisionObject(object.get(), btBroadphaseProxy::StaticFilter,
                                    btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    s->objects.push_back(std::move(object));
  }
  impl_->meshes[mesh.node.key()] = std::move(s);
}

void PhysicsWorld::meshEvicted(const NodeId& node) {
  auto it = impl_->meshes.find(node.key());
  if (it == impl_->meshes.end()) return;
  for (size_t w = 0; w < it->second->objects.size(); ++w)
    impl_->shards[w]->world.removeCollisionObject(it->second->objects[w].get());
  impl_->meshes.erase(it);
}

size_t PhysicsWorld::meshCount() const { return impl_->meshes.size(); }

ThreadTeam& PhysicsWorld::threads() const { return impl_->team; }

}  // namespace globe
