#pragma once
// Where test and benchmark bodies are dropped: the places a quadtree planet gets wrong first
// (the 32 polyhedron vertices, both poles among them; face seams; the ±180° meridian) interleaved
// so that even a few bodies cover every kind, then uniform random directions; or a cluster around
// one direction (many bodies in one valley).
#include <glm/vec3.hpp>

#include <cstdint>
#include <random>
#include <string_view>
#include <vector>

namespace globe {

enum class DropSiteKind : uint8_t { kVertex, kPole, kSeam, kAntimeridian, kRandom, kCluster };
std::string_view dropSiteKindName(DropSiteKind kind);

// Two unit vectors spanning the tangent plane at unit `up` (any rotation about it): body
// footprints, clusters and error probes are laid out in it.
struct TangentFrame {
  glm::dvec3 east{1.0, 0.0, 0.0}, north{0.0, 1.0, 0.0};
};
TangentFrame tangentFrame(const glm::dvec3& up);

struct DropSite {
  glm::dvec3 direction{0.0, 0.0, 1.0};  // unit
  DropSiteKind kind = DropSiteKind::kRandom;
};

// The special places, in the interleaved order: 32 vertices (vertex 0 and 11 are the poles), the
// midpoints and quarter points of the 60 face seams, and ±180° at latitudes 0, ±30, ±60.
std::vector<DropSite> specialDropSites();

// `count` sites: the special ones first (all of them when count is large enough), then uniform
// random directions from `rng`.
std::vector<DropSite> scatteredDropSites(uint32_t count, std::mt19937_64& rng);

// `count` sites uniformly within `radius_m` (arc on the sphere of `sphereRadius_m`) of `centre`.
std::vector<DropSite> clusteredDropSites(uint32_t count, const glm::dvec3& centre, double radius_m,
                                         double sphereRadius_m, std::mt19937_64& rng);

}  // namespace globe
