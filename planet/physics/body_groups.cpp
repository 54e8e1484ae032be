#include "planet/physics/body_groups.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace globe {

namespace {

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Cells of at least 8 m: a cell index fits 21 signed bits per axis for anything within 8 000 km
// of the planet centre, so three pack into one 64-bit key.
constexpr double kMinCell_m = 8.0;
constexpr int64_t kCellBias = int64_t(1) << 20;

uint64_t cellKey(int64_t x, int64_t y, int64_t z) {
  auto part = [](int64_t v) { return uint64_t(std::clamp<int64_t>(v + kCellBias, 0, 2 * kCellBias - 1)); };
  return (part(x) << 42) | (part(y) << 21) | part(z);
}

}  // namespace

std::vector<uint32_t> groupBodies(std::span<const BodyReach> bodies) {
  std::vector<uint32_t> parent(bodies.size());
  for (uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  double maxReach_m = 0.0;
  for (const BodyReach& b : bodies) maxReach_m = std::max(maxReach_m, b.reach_m);
  // Two reach spheres that overlap have centres closer than 2 maxReach: adjacent cells or the same.
  const double cell_m = std::max(kMinCell_m, 2.0 * maxReach_m);
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
  cells.reserve(bodies.size());
  std::vector<std::array<int64_t, 3>> cellOf(bodies.size());
  for (uint32_t i = 0; i < bodies.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) cellOf[i][axis] = int64_t(std::floor(bodies[i].position_m[axis] / cell_m));
    cells[cellKey(cellOf[i][0], cellOf[i][1], cellOf[i][2])].push_back(i);
  }
  for (uint32_t i = 0; i < bodies.size(); ++i) {
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells.find(cellKey(cellOf[i][0] + dx, cellOf[i][1] + dy, cellOf[i][2] + dz));
          if (it == cells.end()) continue;
          for (uint32_t j : it->second) {
            if (j >= i) continue;
            const double reach_m = bodies[i].reach_m + bodies[j].reach_m;
            if (glm::length(bodies[i].position_m - bodies[j].position_m) > reach_m) continue;
            const uint32_t a = findRoot(parent, i), b = findRoot(parent, j);
            parent[std::max(a, b)] = std::min(a, b);  // the root is the group's smallest id
          }
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
