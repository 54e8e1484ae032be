#pragma once
// Helpers shared by the LOD tests: spherical areas, residency fakes, seeded cameras.
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <stdexcept>
#include <unordered_set>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "planet/geometry/ellipsoid.h"
#include "planet/geometry/face_mapping.h"
#include "planet/geometry/node_id.h"
#include "planet/geometry/triacontahedron.h"
#include "planet/lod/lod_ranges.h"
#include "planet/lod/node_residency.h"
#include "planet/lod/roughness_map.h"
#include "planet/lod/selection.h"

namespace globe::testing {

inline constexpr double kEarthRadius_m = 6371000.0;

// Solid angle (steradians) of the spherical triangle with unit corners a, b, c (Van Oosterom &
// Strackee), using differences so tiny deep-level triangles keep their precision.
inline double sphericalTriangleArea(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double triple = glm::dot(a, glm::cross(b - a, c - a));
  const double denominator = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
  return 2.0 * std::atan2(std::abs(triple), denominator);
}

// Node edges are great-circle arcs, so the node is the spherical quadrilateral of its corners.
inline double nodeSolidAngle(const NodeId& id) {
  const FaceMapping& m = RhombusFaceMapping::get();
  const glm::dvec3 c0 = nodeCornerDirection(m, id, 0), c1 = nodeCornerDirection(m, id, 1);
  const glm::dvec3 c2 = nodeCornerDirection(m, id, 2), c3 = nodeCornerDirection(m, id, 3);
  return sphericalTriangleArea(c0, c1, c2) + sphericalTriangleArea(c0, c2, c3);
}

inline glm::dvec3 fromLatLon(double latDeg, double lonDeg) {
  const double lat = latDeg * std::numbers::pi / 180.0;
  const double lon = lonDeg * std::numbers::pi / 180.0;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// Bitwise equality: seam exactness means the same bits, not merely equal values.
inline bool bitEqual(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// (u, v) of parameter s along face edge e, walked from corner e to corner e+1.
inline std::pair<double, double> onEdge(int e, double s) {
  switch (e) {
    case 0:
      return {s, 0.0};
    case 1:
      return {1.0, s};
    case 2:
      return {1.0 - s, 1.0};
    default:
      return {0.0, 1.0 - s};
  }
}

// A node at `level` on a random face and position (face, then x, then y drawn from rng).
inline NodeId randomNodeAt(std::mt19937_64& rng, int level) {
  const uint32_t cells = uint32_t{1} << level;
  const auto face = static_cast<uint8_t>(rng() % 30);
  const auto x = static_cast<uint32_t>(rng() % cells);
  const auto y = static_cast<uint32_t>(rng() % cells);
  return {face, static_cast<uint8_t>(level), x, y};
}

inline glm::dvec3 randomDirection(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  for (;;) {
    const glm::dvec3 d(n(rng), n(rng), n(rng));
    const double l = glm::length(d);
    if (l > 1e-3) return d / l;
  }
}

// A terrain whose real radius range over a node shrinks with the node: |elevation| up to
// min(amplitude, relief * width), with a per-node wobble so diagonals differ between nodes.
// With a flattening, the terrain lies on the ellipsoid of equatorial radius radius_m: the range is the
// distance from the centre of its heights +-a over the node's 3 x 3 grid of geodetic normals.
struct SyntheticTerrain {
  double radius_m = kEarthRadius_m;
  double amplitude_m = 8000.0;
  double relief = 0.05;
  double flattening = 0.0;
  RadiusRange rangeOf(const NodeId& id) const {
    const double wobble = 0.5 + 0.5 * static_cast<double>(NodeIdHash{}(id) % 1024) / 1023.0;
    const double a = std::min(amplitude_m, relief * nominalNodeWidth(id.level, radius_m)) * wobble;
    if (flattening == 0.0) return {radius_m - a, radius_m + a};
    const Ellipsoid shape = Ellipsoid::create(radius_m, flattening).value();
    RadiusRange r{radius_m, 0.0};
    for (int j = 0; j <= 2; ++j) {
      for (int i = 0; i <= 2; ++i) {
        const glm::dvec3 n = RhombusFaceMapping::get().unitPoint(id.face, id.uMin() + id.size() * 0.5 * i,
                                                                 id.vMin() + id.size() * 0.5 * j);
        for (double h : {-a, a}) {
          r.min_m = std::min(r.min_m, glm::length(shape.position(n, h)));
          r.max_m = std::max(r.max_m, glm::length(shape.position(n, h)));
        }
      }
    }
    return r;
  }
  // Geometric error of a node's payload (its parent's mesh vs its own): a fraction of its relief,
  // rough in the northern hemisphere's western half and flat (1 %) elsewhere, so tolerance-driven
  // ranges see terrain that differs between neighbours and across seams.
  double errorOf(const NodeId& id) const {
    const RadiusRange r = rangeOf(id);
    const glm::dvec3 c = RhombusFaceMapping::get().unitPoint(id.face, (id.x + 0.5) / double(1u << id.level),
                                                             (id.y + 0.5) / double(1u << id.level));
    const double roughness = c.z > 0.0 && c.y < 0.0 ? 0.25 : 0.01;
    return roughness * (r.max_m - r.min_m);
  }
};

// A roughness map matching SyntheticTerrain::errorOf: rough (0.25) where z > 0 and y < 0, flat
// (0.01) elsewhere, at every depth — a step the map's grid and slopes must carry without cracks.
inline std::shared_ptr<const RoughnessMap> syntheticRoughnessMap(int maxDepth, double minRadius_m) {
  static const RoughnessMap::Model model = [](const glm::dvec3& d, std::span<double> out) {
    for (double& v : out) v = d.z > 0.0 && d.y < 0.0 ? 0.25 : 0.01;
  };
  return std::make_shared<const RoughnessMap>(RoughnessMap::build(maxDepth, minRadius_m, model));
}

// Every node resident; known ranges from a synthetic terrain (or a smooth sphere when relief = 0).
class AllResident : public NodeResidency {
 public:
  explicit AllResident(SyntheticTerrain terrain = {}) : terrain_(terrain) {}
  bool isResident(const NodeId&) const override { return true; }
  void request(const NodeId&, RequestPriority, double) override { ++requests; }
  std::optional<RadiusRange> knownRadiusRange(const NodeId& id) const override { return terrain_.rangeOf(id); }
  std::optional<double> knownGeometricError(const NodeId& id) const override { return terrain_.errorOf(id); }
  int requests = 0;

 private:
  SyntheticTerrain terrain_;
};

// Levels <= fullLevel resident; deeper nodes resident unless their hash says otherwise.
class PartlyResident : public NodeResidency {
 public:
  PartlyResident(int fullLevel, SyntheticTerrain terrain) : fullLevel_(fullLevel), terrain_(terrain) {}
  bool isResident(const NodeId& id) const override { return id.level <= fullLevel_ || NodeIdHash{}(id) % 5 != 0; }
  void request(const NodeId& id, RequestPriority, double distance_m) override {
    requested.push_back(id);
    distances.push_back(distance_m);
  }
  std::optional<RadiusRange> knownRadiusRange(const NodeId& id) const override {
    if (!isResident(id)) return std::nullopt;
    return terrain_.rangeOf(id);
  }
  std::optional<double> knownGeometricError(const NodeId& id) const override {
    if (!isResident(id)) return std::nullopt;
    return terrain_.errorOf(id);
  }
  std::vector<NodeId> requested;
  std::vector<double> distances;

 private:
  int fullLevel_;
  SyntheticTerrain terrain_;
};

// An Earth-sized selector (elevations within +-8 km). tolerance_px > 0: tolerance-driven ranges (from
// SyntheticTerrain::errorOf), else distance ranges; flattening > 0: on that ellipsoid (WGS84's equatorial
// radius); roughness: with tolerance ranges, following syntheticRoughnessMap (the rough octant of errorOf).
inline LodSelector earthSelector(int maxDepth = 20, bool horizon = true, double tolerance_px = 0.0,
                                 double flattening = 0.0, bool roughness = false) {
  LodConfig c;
  if (flattening > 0.0) {
    c.radius_m = 6378137.0;
    c.flattening = flattening;
  }
  c.ranges.maxDepth = maxDepth;
  c.ranges.tolerance_px = tolerance_px;
  c.minElevation_m = -8000.0;
  c.maxElevation_m = 8000.0;
  c.horizonCulling = horizon;
  auto s = LodSelector::create(c);
  if (!s) throw std::runtime_error(s.error().format());
  if (roughness) s->ranges().setRoughness(syntheticRoughnessMap(maxDepth, c.radius_m * (1 - c.flattening) - 8000.0));
  return std::move(s.value());
}

}  // namespace globe::testing
