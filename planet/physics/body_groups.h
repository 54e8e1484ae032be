#pragma once
// Bodies far apart never interact, so they can be stepped in separate Bullet worlds on separate
// threads. A group is a connected component of bodies whose reach spheres (bounding radius plus the
// distance they can cover before the groups are formed again, plus slack) overlap; every group lives
// in one world. Worlds are a fixed number, not the thread count, so a run's result never depends on
// the machine or on thread timing.
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace globe {

struct BodyReach {
  glm::dvec3 position_m{0.0};  // planet-centred
  double reach_m = 0.0;        // > 0: no body outside this sphere can touch this one before regrouping
};

// For each body, the smallest id of its group (ids are indices into `bodies`).
std::vector<uint32_t> groupBodies(std::span<const BodyReach> bodies);

// The world of each body: a group whose members are all in one world stays there; a group spread
// over several worlds (groups that met) moves to the world of its smallest id. Bodies without a
// world yet (`previous` shorter than `groups`) start in world id % worlds, which spreads scattered
// bodies evenly. Deterministic: a function of its arguments only.
std::vector<uint32_t> assignWorlds(std::span<const uint32_t> groups, std::span<const uint32_t> previous,
                                   uint32_t worlds);

}  // namespace globe
