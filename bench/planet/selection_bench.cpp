// CDLOD selection cost (docs/lod.md): nodes visited, nodes selected and time per visited node at
// camera altitudes 1 m .. 1e8 m over a 6371 km planet, max depth 20, all nodes resident with known
// (tightened) radius ranges from a synthetic terrain. "Frustum": 60° vertical, 16:9, looking at the
// horizon; "All": no frustum culling (horizon culling only). "SelectionWGS84": the same on the WGS84
// ellipsoid (a = 6378137 m), the camera at the same geodetic place and ellipsoidal height.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "planet/lod/roughness_map.h"
#include "planet/lod/selection.h"

namespace globe {
namespace {

constexpr double kRadius_m = 6371000.0;

// Terrain relief shrinking with the node (5 % of its width, at most 8 km), like real payload ranges.
// On an ellipsoid: the distance of the node centre's surface point, widened by the relief and by the
// slope of the ellipsoid against the spheres |p| = r (f node widths).
class ResidentTerrain final : public NodeResidency {
 public:
  explicit ResidentTerrain(const Ellipsoid& shape) : shape_(shape) {}
  bool isResident(const NodeId&) const override { return true; }
  void request(const NodeId&, RequestPriority, double) override {}
  std::optional<RadiusRange> knownRadiusRange(const NodeId& id) const override {
    const double width = nominalNodeWidth(id.level, shape_.equatorialRadius_m());
    const double a = std::min(8000.0, 0.05 * width);
    if (shape_.isSphere()) return RadiusRange{kRadius_m - a, kRadius_m + a};
    const glm::dvec3 n = nodeCentreDirection(RhombusFaceMapping::get(), id);
    const double r = glm::length(shape_.surfacePoint(n));
    const double slope = shape_.flattening() * width;
    return RadiusRange{r - a - slope, r + a + slope};
  }
  // Geometric error (tolerance-driven ranges): 0.2 % of the node width, 25x that in one octant.
  std::optional<double> knownGeometricError(const NodeId& id) const override {
    const glm::dvec3 c = nodeCentreDirection(RhombusFaceMapping::get(), id);
    return (c.z > 0.0 && c.y < 0.0 ? 0.05 : 0.002) * nominalNodeWidth(id.level, shape_.equatorialRadius_m());
  }

 private:
  Ellipsoid shape_;
};

// The rough octant of ResidentTerrain::knownGeometricError as a roughness map.
std::shared_ptr<const RoughnessMap> octantRoughness(int maxDepth) {
  static const RoughnessMap::Model model = [](const glm::dvec3& d, std::span<double> out) {
    for (double& v : out) v = d.z > 0.0 && d.y < 0.0 ? 0.05 : 0.002;
  };
  return std::make_shared<const RoughnessMap>(RoughnessMap::build(maxDepth, kRadius_m - 8000.0, model));
}

enum class Ranges { kDistance, kTolerance, kRoughness };  // the last two: 2 px, per depth / per place

void selection(benchmark::State& state, double altitude_m, bool withFrustum, double flattening, Ranges ranges) {
  const Ellipsoid shape =
      flattening == 0.0 ? Ellipsoid::sphere(kRadius_m) : Ellipsoid::create(6378137.0, flattening).value();
  LodConfig config;
  config.radius_m = shape.equatorialRadius_m();
  config.flattening = flattening;
  config.minElevation_m = -8000.0;
  config.maxElevation_m = 8000.0;
  config.ranges.maxDepth = 20;
  config.ranges.tolerance_px = ranges == Ranges::kDistance ? 0.0 : 2.0;
  auto selector = LodSelector::create(config);
  if (!selector) {
    state.SkipWithError(selector.error().format().c_str());
    return;
  }
  if (ranges == Ranges::kRoughness) selector->ranges().setRoughness(octantRoughness(config.ranges.maxDepth));
  const double lat = 46.5 * std::numbers::pi / 180.0;
  const double lon = 7.5 * std::numbers::pi / 180.0;
  const glm::dvec3 up(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
  const glm::dvec3 eye = shape.position(up, altitude_m);
  const glm::dvec3 north = glm::normalize(glm::dvec3(0, 0, 1) - up * up.z);
  // Look at the horizon (or straight down from far away, where the horizon is below the view).
  const double dip = std::acos(std::min(1.0, kRadius_m / (kRadius_m + altitude_m)));
  const glm::dvec3 forward = altitude_m > 1e6 ? -up : glm::normalize(north * std::cos(dip) - up * std::sin(dip));
  const glm::dmat4 viewProjection = glm::perspective(std::numbers::pi / 3.0, 16.0 / 9.0, 0.01, 1e12) *
                                    glm::lookAt(eye, eye + forward, altitude_m > 1e6 ? north : up);
  const auto frustum = Frustum::fromViewProjection(viewProjection);
  const SelectionCamera camera{eye, withFrustum ? &frustum.value() : nullptr};
  ResidentTerrain residency(shape);
  Selection out;
  (void)selector->select(camera, residency, out);  // warm-up: ranges settle, the buffer grows once
  for (auto _ : state) {
    const Status s = selector->select(camera, residency, out);
    benchmark::DoNotOptimize(s.ok());
    benchmark::DoNotOptimize(out.nodes.data());
  }
  const double visited = out.stats.visited;
  state.counters["visited"] = visited;
  state.counters["selected"] = static_cast<double>(out.stats.selected);
  state.counters["partial"] = static_cast<double>(out.stats.partial);
  state.counters["passes"] = static_cast<double>(out.stats.passes);
  // Frustum-culled nodes the ring prefetch walked (not in `visited`; their time is in the total).
  state.counters["ring_visited"] = static_cast<double>(out.stats.prefetchVisited);
  // Seconds per visited node (shown with an SI prefix, e.g. "60n" = 60 ns).
  state.counters["t_per_visited"] =
      benchmark::Counter(visited, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void registerAll() {
  for (double flattening : {0.0, 1.0 / 298.257223563}) {
    for (bool frustum : {true, false}) {
      for (double altitude : {1.0, 100.0, 1e4, 1e6, 1e8}) {
        const std::string name = std::string(flattening == 0.0 ? "Selection/" : "SelectionWGS84/") +
                                 (frustum ? "Frustum" : "All") + "/altitude_m:" +
                                 (altitude < 1e4 ? std::to_string(static_cast<int>(altitude))
                                                 : (altitude == 1e4   ? "1e4"
                                                    : altitude == 1e6 ? "1e6"
                                                                      : "1e8"));
        benchmark::RegisterBenchmark(name.c_str(), selection, altitude, frustum, flattening, Ranges::kDistance)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
  for (const auto& [prefix, ranges] : {std::pair{"SelectionTolerance/Frustum/altitude_m:", Ranges::kTolerance},
                                       {"SelectionRoughness/Frustum/altitude_m:", Ranges::kRoughness}}) {
    for (const auto& [label, altitude] : {std::pair{"1", 1.0}, {"1e4", 1e4}, {"1e6", 1e6}}) {
      benchmark::RegisterBenchmark((std::string(prefix) + label).c_str(), selection, altitude, true, 0.0, ranges)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  // Recomputing the roughness range fields (once per selection pass after an observation grew).
  benchmark::RegisterBenchmark("RoughnessFieldRecompute", [](benchmark::State& state) {
    LodRangeConfig config;
    config.maxDepth = 24;
    config.tolerance_px = 2.0;
    LodRanges ranges = LodRanges::create(config, kRadius_m).value();
    ranges.setRoughness(octantRoughness(config.maxDepth));
    for (int d = 1; d < config.maxDepth; ++d) ranges.observeError(d, 1e4 * std::pow(0.5, d));
    double lambda = 600.0;
    for (auto _ : state) {
      ranges.setPixelsPerRadian(lambda += 1.0);  // every field changes
      ranges.refresh();
    }
  })->Unit(benchmark::kMillisecond);
}

const int kRegistered = (registerAll(), 0);

}  // namespace
}  // namespace globe
