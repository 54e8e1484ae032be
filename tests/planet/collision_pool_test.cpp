// The collision-mesh pool (planet/physics/collision_mesh_pool.h) and its meshes: seam-exact CPU
// meshes, the budget, eviction by distance, pinned nodes, synchronous versus queued generation.
#include "planet/model/planet_file.h"
#include "planet/physics/collision_mesh_pool.h"

#include <gtest/gtest.h>

#include <cstring>
#include <set>

namespace globe {
namespace {

const ElevationModel& testModel() {
  static const ElevationModel model(*loadPlanetFile(GLOBE_SOURCE_DIR "/assets/planets/earthlike.toml"));
  return model;
}

struct RecordingListener final : CollisionMeshListener {
  std::set<uint64_t> resident;
  void meshResident(const CollisionMesh& mesh) override { resident.insert(mesh.node.key()); }
  void meshEvicted(const NodeId& node) override { resident.erase(node.key()); }
};

// Neighbouring meshes across a face seam share their edge vertices bit for bit (centre + vertex).
TEST(CollisionMesh, NeighboursAcrossASeamShareTheirEdge) {
  CpuCollisionMeshSource source(testModel(), 16);
  const int level = 10;
  const NodeId a{3, uint8_t(level), 0, 17};  // on face 3's edge 3 (u = 0)
  const NodeId b = edgeNeighbour(a, kEdgeMinusU);
  ASSERT_NE(a.face, b.face);
  const CollisionMesh ma = source.generateNow(a), mb = source.generateNow(b);
  std::vector<glm::dvec3> edgeA, edgeB;
  for (uint32_t j = 0; j <= 16; ++j) edgeA.push_back(ma.centre_m + ma.vertex(0, j));
  for (uint32_t i = 0; i <= 16; ++i)
    for (uint32_t j = 0; j <= 16; ++j)
      if (i == 0 || j == 0 || i == 16 || j == 16) edgeB.push_back(mb.centre_m + mb.vertex(i, j));
  for (const glm::dvec3& p : edgeA) {
    bool found = false;
    for (const glm::dvec3& q : edgeB) found = found || std::memcmp(&p, &q, sizeof p) == 0;
    EXPECT_TRUE(found) << "seam vertex not shared bit-exactly";
  }
  EXPECT_EQ(collisionGridIndices(16).size(), size_t(6 * 16 * 16));
}

TEST(CollisionMeshPool, QueuedRequestsArriveNextStepNearestFirst) {
  CpuCollisionMeshSource source(testModel(), 16);
  RecordingListener listener;
  CollisionPoolConfig config;
  config.dispatchBudget = 2;
  CollisionMeshPool pool(config, source, listener);
  pool.beginStep(1);
  const NodeId far{0, 12, 5, 5}, near{0, 12, 6, 5}, mid{0, 12, 7, 5};
  pool.request(far, 300.0);
  pool.request(near, 10.0);
  pool.request(mid, 100.0);
  pool.dispatch();
  EXPECT_FALSE(pool.isResident(near)) << "queued generation is asynchronous";
  pool.beginStep(2);
  EXPECT_TRUE(pool.isResident(near));
  EXPECT_TRUE(pool.isResident(mid));
  EXPECT_FALSE(pool.isResident(far)) << "budget of two per step, nearest first";
  pool.dispatch();
  pool.beginStep(3);
  EXPECT_TRUE(pool.isResident(far));
  EXPECT_EQ(pool.stats().generatedAsync, 3u);
  EXPECT_EQ(pool.stats().generatedSync, 0u);
  pool.requireNow({0, 12, 9, 9}, 0.0);
  EXPECT_TRUE(pool.isResident({0, 12, 9, 9}));
  EXPECT_EQ(pool.stats().generatedSync, 1u);
  EXPECT_EQ(listener.resident.size(), 4u);
}

TEST(CollisionMeshPool, EvictsTheFarthestButNeverATouchedNode) {
  CpuCollisionMeshSource source(testModel(), 16);
  RecordingListener listener;
  CollisionPoolConfig config;
  config.budget_MiB = 3.5 * double(collisionMeshBytes(16)) / (1024.0 * 1024.0);  // room for three
  CollisionMeshPool pool(config, source, listener);
  const NodeId touched{1, 12, 1, 1}, near{1, 12, 2, 1}, far{1, 12, 3, 1}, next{1, 12, 4, 1};
  pool.beginStep(1);
  pool.requireNow(touched, 900.0);  // far from the objects, but a body rests on it
  pool.requireNow(far, 500.0);
  pool.requireNow(near, 5.0);
  pool.pin(touched);
  pool.beginStep(2);
  pool.pin(touched);
  pool.request(near, 5.0);
  pool.request(far, 500.0);
  pool.request(touched, 900.0);
  pool.request(next, 1.0);
  pool.dispatch();
  pool.beginStep(3);
  EXPECT_TRUE(pool.isResident(touched)) << "a touched node is never evicted";
  EXPECT_TRUE(pool.isResident(next));
  EXPECT_TRUE(pool.isResident(near));
  EXPECT_FALSE(pool.isResident(far)) << "the farthest untouched node goes first";
  EXPECT_EQ(pool.stats().evicted, 1u);
  EXPECT_LE(pool.stats().residentBytes, pool.budgetBytes());
  EXPECT_EQ(listener.resident.count(far.key()), 0u);
}

TEST(CollisionMeshPool, ConfigIsValidated) {
  CollisionPoolConfig c;
  c.budget_MiB = 0.0;
  EXPECT_EQ(validateCollisionPoolConfig(c).error().field, "budget_MiB");
  c = {};
  c.dispatchBudget = 0;
  EXPECT_FALSE(validateCollisionPoolConfig(c).ok());
}

}  // namespace
}  // namespace globe
