#include "planet/physics/mesh_error.h"

#include "planet/analysis/percentile.h"
#include "planet/physics/drop_sites.h"
#include "planet/streaming/payload_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace globe {

namespace {

double drawnMinusExact(const ElevationModel& model, const glm::dvec3& direction, int level, uint32_t cells) {
  return drawnSurfaceRadius(model, direction, level, cells) - (model.radius_m() + model.elevation_m(direction));
}

}  // namespace

double meshErrorNear(const ElevationModel& model, const glm::dvec3& centre, double arc_m, int level, uint32_t cells) {
  const auto [east, north] = tangentFrame(centre);
  double worst = 0.0;
  for (int a = -4; a <= 4; ++a) {
    for (int b = -4; b <= 4; ++b) {
      const glm::dvec3 offset = (double(a) * east + double(b) * north) * (0.25 * arc_m / model.radius_m());
      worst = std::max(worst, std::abs(drawnMinusExact(model, glm::normalize(centre + offset), level, cells)));
    }
  }
  return worst;
}

MeshErrorStats measureMeshError(const ElevationModel& model, int level, uint32_t cells, uint32_t samples,
                                uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<double> errors;
  errors.reserve(samples);
  MeshErrorStats stats;
  double sum = 0.0;
  for (uint32_t k = 0; k < samples; ++k) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
    const double e = drawnMinusExact(model, d, level, cells);
    sum += e;
    errors.push_back(std::abs(e));
  }
  stats.samples = samples;
  if (samples == 0) return stats;
  stats.meanSigned_m = sum / double(samples);
  std::sort(errors.begin(), errors.end());
  stats.p50_m = nearestRankPercentile(errors, 50);
  stats.p99_m = nearestRankPercentile(errors, 99);
  stats.max_m = errors.back();
  return stats;
}

}  // namespace globe
