// The collision selection (planet/physics/collision_selection.h): complete within the radius of
// interest across face seams and at polyhedron vertices, and the predicted-contact test.
#include "planet/physics/collision_selection.h"
#include "planet/geometry/face_mapping.h"
#include "planet/lod/lod_ranges.h"
#include "planet/physics/collision_selection_worker.h"
#include "planet/physics/drop_sites.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <random>
#include <set>

namespace globe {
namespace {

constexpr double kRadius_m = 6371000.0;

std::set<uint64_t> keysOf(const std::vector<SelectedCollisionNode>& nodes) {
  std::set<uint64_t> keys;
  for (const auto& n : nodes) keys.insert(n.node.key());
  return keys;
}

// Every point within the radius (sampled densely) lies in a selected node, at every special place.
TEST(CollisionSelection, CoversTheRadiusAcrossSeamsAndVertices) {
  const auto& mapping = RhombusFaceMapping::get();
  const int level = 12;
  const double radius = 0.7 * nominalNodeWidth(level, kRadius_m);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const DropSite& site : specialDropSites()) {
    std::vector<SelectedCollisionNode> nodes;
    selectCollisionNodes(mapping, kRadius_m, {site.direction * kRadius_m, radius}, level, nodes);
    const std::set<uint64_t> keys = keysOf(nodes);
    ASSERT_EQ(keys.size(), nodes.size()) << "a node selected twice";
    const glm::dvec3 up = site.direction;
    const auto [east, north] = tangentFrame(up);
    for (int k = 0; k < 400; ++k) {
      const double arc = radius / kRadius_m * std::sqrt(unit(rng)), az = 6.283185307179586 * unit(rng);
      const glm::dvec3 d = std::cos(arc) * up + std::sin(arc) * (std::cos(az) * east + std::sin(az) * north);
      const NodeId at = nodeAt(mapping.locate(d), level);
      ASSERT_TRUE(keys.count(at.key())) << dropSiteKindName(site.kind) << " misses face " << int(at.face);
    }
    if (site.kind == DropSiteKind::kPole) {
      EXPECT_GE(nodes.size(), 5u) << "five faces meet at a pole";
    }
    EXPECT_LE(nodes.size(), 16u) << "far more nodes than the radius needs";
  }
}

TEST(CollisionSelection, WorkerMatchesTheDirectSelection) {
  const auto& mapping = RhombusFaceMapping::get();
  CollisionSelectionWorker worker(mapping, kRadius_m, 13);
  std::vector<ObjectQuery> queries;
  for (const DropSite& s : specialDropSites())
    queries.push_back({uint32_t(queries.size()), {s.direction * (kRadius_m + 50.0), 40.0}, 0.0});
  const uint64_t round = worker.submit(queries);
  worker.waitFor(round);
  CollisionSelectionRound result;
  ASSERT_TRUE(worker.take(result));
  EXPECT_EQ(result.round, round);
  std::set<uint64_t> direct;
  for (const ObjectQuery& q : queries) {
    std::vector<SelectedCollisionNode> nodes;
    selectCollisionNodes(mapping, kRadius_m, q.query, 13, nodes);
    for (const auto& n : nodes) direct.insert(n.node.key());
  }
  EXPECT_EQ(keysOf(result.nodes), direct);
  EXPECT_TRUE(std::is_sorted(result.nodes.begin(), result.nodes.end(),
                             [](const auto& a, const auto& b) { return a.distance_m < b.distance_m; }));
  EXPECT_FALSE(worker.take(result)) << "a round is handed out once";
}

TEST(CollisionSelection, PredictsContactFromVelocityAndStep) {
  const double dt = 1.0 / 120.0, ground = kRadius_m;
  const glm::dvec3 up(0, 0, 1);
  // 1 m sphere, lowest point 1 m above the ground.
  BodyMotion resting{up * (ground + 1.5), glm::dvec3(0.0), 0.5};
  EXPECT_FALSE(predictsContact(resting, dt, ground));
  // Falling at 50 m/s: 0.83 m in the two-step look-ahead, not yet.
  BodyMotion falling{up * (ground + 1.5), -up * 50.0, 0.5};
  EXPECT_FALSE(predictsContact(falling, dt, ground));
  // At 70 m/s it reaches the ground within the look-ahead.
  falling.velocity_m_s = -up * 70.0;
  EXPECT_TRUE(predictsContact(falling, dt, ground));
  // Moving away never predicts contact from above.
  falling.velocity_m_s = up * 70.0;
  EXPECT_FALSE(predictsContact(falling, dt, ground));
  // The swept query holds the start and end of the look-ahead.
  const CollisionQuery q = sweptContactQuery({up * ground, glm::dvec3(12.0, 0, 0), 0.5}, dt, 0.1);
  EXPECT_NEAR(glm::length(q.position_m - up * ground), 0.1, 1e-9);
  EXPECT_NEAR(q.radius_m, 0.1 + 0.5 + 0.1, 1e-9);
}

}  // namespace
}  // namespace globe
