#include "planet/physics/body_groups.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace globe {

namespace {

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<uint32_t> groupBodies(std::span<const BodyReach> bodies) {
  std::vector<uint32_t> parent(bodies.size());
  for (uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  // Sweep and prune along the axis the bodies spread most on: two reach spheres overlap only if
  // their intervals on it do, so in order of the intervals' low ends each body is compared with
  // the bodies whose interval starts before its own ends (for bodies scattered over a planet,
  // about one; in a crowd, its neighbours along that axis).
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
  for (const BodyReach& b : bodies) {
    low = glm::min(low, b.position_m);
    high = glm::max(high, b.position_m);
  }
  const glm::dvec3 spread = high - low;
  const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
  std::vector<std::pair<double, uint32_t>> order(bodies.size());  // (interval's low end, id)
  for (uint32_t i = 0; i < bodies.size(); ++i) order[i] = {bodies[i].position_m[axis] - bodies[i].reach_m, i};
  std::sort(order.begin(), order.end());
  for (size_t a = 0; a < order.size(); ++a) {
    const uint32_t i = order[a].second;
    const double end_m = bodies[i].position_m[axis] + bodies[i].reach_m;
    for (size_t b = a + 1; b < order.size() && order[b].first <= end_m; ++b) {
      const uint32_t j = order[b].second;
      if (glm::length(bodies[i].position_m - bodies[j].position_m) > bodies[i].reach_m + bodies[j].reach_m) continue;
      const uint32_t ri = findRoot(parent, i), rj = findRoot(parent, j);
      parent[std::max(ri, rj)] = std::min(ri, rj);  // the root is the group's smallest id
    }
  }
  for (uint32_t i = 0; i < parent.size(); ++i) parent[i] = findRoot(parent, i);
  return parent;
}

std::vector<uint32_t> assignWorlds(std::span<const uint32_t> groups, std::span<const uint32_t> previous,
                                   uint32_t worlds) {
  worlds = std::max(worlds, 1u);
  auto before = [&](uint32_t i) { return i < previous.size() ? previous[i] : i % worlds; };
  // A group keeps its world when all its members agree; groups are listed by their smallest id,
  // which comes first in id order, so one pass finds the disagreeing groups.
  constexpr uint32_t kUnset = ~0u, kSplit = ~0u - 1;
  std::vector<uint32_t> common(groups.size(), kUnset);
  for (uint32_t i = 0; i < groups.size(); ++i) {
    uint32_t& c = common[groups[i]];
    if (c == kUnset)
      c = before(i);
    else if (c != before(i))
      c = kSplit;
  }
  std::vector<uint32_t> world(groups.size());
  for (uint32_t i = 0; i < groups.size(); ++i) {
    const uint32_t root = groups[i];
    world[i] = common[root] == kSplit ? before(root) : common[root];
  }
  return world;
}

}  // namespace globe
