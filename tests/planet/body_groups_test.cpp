// Groups of bodies that may meet, and the Bullet world each group lives in
// (planet/physics/body_groups.h).
#include "planet/physics/body_groups.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <random>

namespace globe {
namespace {

TEST(BodyGroups, BodiesWithinReachJoinTransitivelyFarOnesStayApart) {
  const glm::dvec3 base{6371000.0, 0.0, 0.0};
  const std::vector<BodyReach> bodies = {
      {base, 1.0},                            // 0
      {base + glm::dvec3(0, 500, 0), 1.0},    // 1: far from everything
      {base + glm::dvec3(0, 0, 1.9), 1.0},    // 2: reaches 0
      {base + glm::dvec3(0, 0, 3.8), 1.0},    // 3: reaches 2, so 0 too
      {base + glm::dvec3(0, 0, 24.0), 20.0},  // 4: a long reach (fast body) that reaches 3
      {-base, 1.0},                           // 5: the other side of the planet
  };
  EXPECT_EQ(groupBodies(bodies), (std::vector<uint32_t>{0, 1, 0, 0, 0, 5}));
}

// The sweep along one axis finds every overlapping pair: the same groups as comparing every pair, for
// a crowd with short and long reaches.
TEST(BodyGroups, SameGroupsAsComparingEveryPair) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> spread(-60.0, 60.0), reach(0.5, 3.0);
  std::vector<BodyReach> bodies;
  for (int i = 0; i < 400; ++i)
    bodies.push_back({glm::dvec3(6371000.0 + spread(rng), spread(rng), spread(rng)), i % 50 == 0 ? 15.0 : reach(rng)});
  std::vector<uint32_t> parent(bodies.size());
  for (uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto root = [&](uint32_t i) {
    while (parent[i] != i) i = parent[i];
    return i;
  };
  for (uint32_t i = 0; i < bodies.size(); ++i)
    for (uint32_t j = 0; j < i; ++j)
      if (glm::length(bodies[i].position_m - bodies[j].position_m) <= bodies[i].reach_m + bodies[j].reach_m) {
        const uint32_t a = root(i), b = root(j);
        parent[std::max(a, b)] = std::min(a, b);
      }
  for (uint32_t i = 0; i < parent.size(); ++i) parent[i] = root(i);
  EXPECT_EQ(groupBodies(bodies), parent);
}

TEST(BodyGroups, GroupsKeepTheirWorldAndMeetingGroupsMoveToTheSmallestId) {
  const std::vector<uint32_t> groups = {0, 1, 0, 3, 3, 5};
  // Bodies 0 and 2 were apart (worlds 0 and 1) and met; 3 and 4 were already together in world 1.
  const std::vector<uint32_t> previous = {0, 1, 1, 1, 1};
  EXPECT_EQ(assignWorlds(groups, previous, 2), (std::vector<uint32_t>{0, 1, 0, 1, 1, 1}))
      << "body 5 is new: world 5 % 2";
  EXPECT_EQ(assignWorlds(groups, {}, 1), (std::vector<uint32_t>(6, 0)));
}

}  // namespace
}  // namespace globe
