#include "planet/physics/physics_world.h"

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

// A static terrain mesh: Bullet's view of the pool's vertices (shared, not copied) and the shared
// index grid, its BVH and its object at the node centre.
struct StaticMesh {
  NodeId node;
  btIndexedMesh part;
  std::unique_ptr<btTriangleIndexVertexArray> array;
  std::unique_ptr<btBvhTriangleMeshShape> shape;
  std::unique_ptr<btCollisionObject> object;
};

struct Body {
  BodySpec spec;
  std::unique_ptr<btCollisionShape> shape;
  std::unique_ptr<btDefaultMotionState> motion;
  std::unique_ptr<btRigidBody> rigid;
  std::vector<NodeId> contacts;
  double boundingRadius_m = 0.0;
};

}  // namespace

struct PhysicsWorld::Impl {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::vector<Body> bodies;
  std::unordered_map<uint64_t, std::unique_ptr<StaticMesh>> meshes;
  std::unordered_map<uint32_t, std::vector<int>> indices;  // per cells
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

PhysicsWorld::PhysicsWorld(const PhysicsSettings& settings) : settings_(settings), impl_(std::make_unique<Impl>()) {
  impl_->world.setGravity(btVector3(0, 0, 0));  // radial, per body (step())
  // Terrain meshes never move: only active bodies' bounds are updated each step (Bullet's default
  // recomputes every object's, ~10 % of a step with 1 600 meshes resident).
  impl_->world.setForceUpdateAllAabbs(false);
  gCalculateCombinedRollingFrictionCallback = &combinedRollingFriction;
  gCalculateCombinedSpinningFrictionCallback = &combinedRollingFriction;
}

PhysicsWorld::~PhysicsWorld() {
  for (Body& b : impl_->bodies) impl_->world.removeRigidBody(b.rigid.get());
  for (auto& [key, mesh] : impl_->meshes) impl_->world.removeCollisionObject(mesh->object.get());
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
  body.motion = std::make_unique<btDefaultMotionState>(btTransform(toBt(spec.orientation), toBt(spec.position_m)));
  btRigidBody::btRigidBodyConstructionInfo info(mass, body.motion.get(), body.shape.get(), inertia);
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
  // Continuous collision: a body moving more than a quarter of its size in a step is swept, so a
  // 50 m/s impact cannot tunnel through a one-sided terrain triangle.
  body.rigid->setCcdMotionThreshold(0.25 * spec.size_m);
  body.rigid->setCcdSweptSphereRadius(0.4 * spec.size_m);
  const uint32_t id = uint32_t(impl_->bodies.size());
  body.rigid->setUserIndex(int(id));
  impl_->world.addRigidBody(body.rigid.get());
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

void PhysicsWorld::step() {
  const double g0 = settings_.surfaceGravity_m_s2, r0 = settings_.planetRadius_m;
  for (Body& b : impl_->bodies) {
    if (!b.rigid->isActive()) continue;
    const glm::dvec3 p = fromBt(b.rigid->getCenterOfMassPosition());
    const double r = glm::length(p);
    b.rigid->setGravity(toBt(p * (-g0 * (r0 / r) * (r0 / r) / r)));
  }
  impl_->world.stepSimulation(settings_.step_s, 0);  // 0 substeps: exactly one step of step_s
  for (Body& b : impl_->bodies) b.contacts.clear();
  const int manifolds = impl_->dispatcher.getNumManifolds();
  for (int m = 0; m < manifolds; ++m) {
    const btPersistentManifold* manifold = impl_->dispatcher.getManifoldByIndexInternal(m);
    if (manifold->getNumContacts() == 0) continue;
    const btCollisionObject* a = manifold->getBody0();
    const btCollisionObject* b = manifold->getBody1();
    if (a->getUserIndex() < 0) std::swap(a, b);
    if (a->getUserIndex() < 0 || b->getUserIndex() >= 0) continue;  // body-body or mesh-mesh
    impl_->bodies[size_t(a->getUserIndex())].contacts.push_back(
        static_cast<const StaticMesh*>(b->getUserPointer())->node);
  }
}

std::span<const NodeId> PhysicsWorld::contactNodes(uint32_t id) const { return impl_->bodies[id].contacts; }

std::optional<double> PhysicsWorld::rayCastMeshes(const glm::dvec3& origin_m, const glm::dvec3& direction,
                                                  double maxDistance_m) const {
  const btVector3 from = toBt(origin_m), to = toBt(origin_m + direction * maxDistance_m);
  btCollisionWorld::ClosestRayResultCallback hit(from, to);
  hit.m_collisionFilterMask = btBroadphaseProxy::StaticFilter;
  impl_->world.rayTest(from, to, hit);
  if (!hit.hasHit()) return std::nullopt;
  return hit.m_closestHitFraction * maxDistance_m;
}

void PhysicsWorld::meshResident(const CollisionMesh& mesh) {
  auto& indices = impl_->indices[mesh.cells];
  if (indices.empty()) indices = collisionGridIndices(mesh.cells);
  auto s = std::make_unique<StaticMesh>();
  s->node = mesh.node;
  s->part.m_numTriangles = int(indices.size() / 3);
  s->part.m_triangleIndexBase = reinterpret_cast<const unsigned char*>(indices.data());
  s->part.m_triangleIndexStride = 3 * sizeof(int);
  s->part.m_numVertices = int(mesh.vertexCount());
  s->part.m_vertexBase = reinterpret_cast<const unsigned char*>(mesh.vertices_m.data());
  s->part.m_vertexStride = 3 * sizeof(double);
  s->part.m_indexType = PHY_INTEGER;
  s->part.m_vertexType = PHY_DOUBLE;
  s->array = std::make_unique<btTriangleIndexVertexArray>();
  s->array->addIndexedMesh(s->part, PHY_INTEGER);
  s->shape = std::make_unique<btBvhTriangleMeshShape>(s->array.get(), /*useQuantizedAabbCompression=*/true);
  s->shape->setMargin(settings_.meshMargin_m);
  s->object = std::make_unique<btCollisionObject>();
  s->object->setCollisionShape(s->shape.get());
  s->object->setWorldTransform(btTransform(btQuaternion::getIdentity(), toBt(mesh.centre_m)));
  s->object->setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
  s->object->setFriction(1.0);
  s->object->setRollingFriction(0.0);  // the pair's rolling friction is the body's (see addBody)
  s->object->setRestitution(1.0);
  s->object->setUserIndex(-1);
  s->object->setUserPointer(s.get());
  impl_->world.addCollisionObject(s->object.get(), btBroadphaseProxy::StaticFilter,
                                  btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
  impl_->meshes[mesh.node.key()] = std::move(s);
}

void PhysicsWorld::meshEvicted(const NodeId& node) {
  auto it = impl_->meshes.find(node.key());
  if (it == impl_->meshes.end()) return;
  impl_->world.removeCollisionObject(it->second->object.get());
  impl_->meshes.erase(it);
}

size_t PhysicsWorld::meshCount() const { return impl_->meshes.size(); }

}  // namespace globe
