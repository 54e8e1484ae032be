#include "planet/analysis/screen_error.h"

#include "planet/analysis/percentile.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace globe {

namespace {

// Distance (pixels) from sample (c, r) to the nearest sample whose rendered answer is `wanted`,
// searched in growing square rings (Chebyshev), the Euclidean minimum taken within the ring where
// the first match appears and the next one (a nearer Euclidean match can sit one ring out).
double nearestRenderedAs(const std::vector<uint8_t>& renderedHit, uint32_t columns, uint32_t rows, uint32_t c,
                         uint32_t r, uint8_t wanted, uint32_t stride) {
  const int64_t maxRing = int64_t(std::max(columns, rows));
  double best = std::numeric_limits<double>::infinity();
  int64_t foundRing = -1;
  for (int64_t ring = 1; ring <= maxRing; ++ring) {
    if (foundRing >= 0 && double(ring) > best) break;
    for (int64_t dy = -ring; dy <= ring; ++dy)
      for (int64_t dx = -ring; dx <= ring; ++dx) {
        if (std::max(std::abs(dx), std::abs(dy)) != ring) continue;
        int64_t x = int64_t(c) + dx, y = int64_t(r) + dy;
        if (x < 0 || y < 0 || x >= int64_t(columns) || y >= int64_t(rows)) continue;
        if (renderedHit[size_t(y) * columns + size_t(x)] != wanted) continue;
        best = std::min(best, std::sqrt(double(dx * dx + dy * dy)));
        if (foundRing < 0) foundRing = ring;
      }
  }
  return std::isfinite(best) ? best * stride : double(maxRing) * stride;
}

}  // namespace

ScreenError measureScreenError(const SurfaceTruth& truth, const std::vector<double>& rendered, const Camera& camera) {
  assert(rendered.size() == size_t(truth.width) * truth.height);
  ScreenError e;
  const double pixelAngle = camera.verticalFov_rad / double(truth.height);
  std::vector<double> px, metres;
  std::vector<uint8_t> renderedHit(truth.hits.size(), 0);
  std::vector<uint32_t> mismatches;
  for (uint32_t r = 0; r < truth.rows; ++r)
    for (uint32_t c = 0; c < truth.columns; ++c) {
      const size_t i = size_t(r) * truth.columns + c;
      const SurfaceRayHit& hit = truth.hits[i];
      uint32_t x = std::min(truth.pixelX(c), truth.width - 1), y = std::min(truth.pixelY(r), truth.height - 1);
      double t = rendered[size_t(y) * truth.width + x];
      bool drawn = std::isfinite(t);
      renderedHit[i] = drawn;
      ++e.samples;
      if (hit.kind == SurfaceRayHit::Kind::kUnresolved) {
        ++e.unresolved;
        renderedHit[i] = 2;  // neither answer is known: never counted as a correct neighbour
        continue;
      }
      bool truthHit = hit.kind == SurfaceRayHit::Kind::kHit;
      if (drawn != truthHit) {
        mismatches.push_back(uint32_t(i));
        continue;
      }
      if (!drawn) continue;
      ++e.bothHit;
      glm::dvec3 dir = pixelRay(camera, truth.width, truth.height, x, y);
      glm::dvec3 truePoint = camera.position_m + hit.distance_m * dir;
      glm::dvec3 drawnPoint = camera.position_m + t * dir;
      // Nearest true surface point to the drawn one, on the tangent plane at the true hit.
      glm::dvec3 nearest = drawnPoint - glm::dot(drawnPoint - truePoint, hit.normal) * hit.normal;
      glm::dvec3 a = drawnPoint - camera.position_m, b = nearest - camera.position_m;
      double angle = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
      px.push_back(angle / pixelAngle);
      metres.push_back(std::abs(t - hit.distance_m));
    }
  auto fill = [](std::vector<double>& v, double& p50, double& p95, double& mx) {
    if (v.empty()) return;
    std::sort(v.begin(), v.end());
    p50 = nearestRankPercentile(v, 50);
    p95 = nearestRankPercentile(v, 95);
    mx = v.back();
  };
  fill(px, e.p50_px, e.p95_px, e.max_px);
  fill(metres, e.p50_m, e.p95_m, e.max_m);
  e.silhouetteMismatches = uint32_t(mismatches.size());
  for (uint32_t i : mismatches) {
    uint32_t c = i % truth.columns, r = i / truth.columns;
    uint8_t wanted = truth.hits[i].kind == SurfaceRayHit::Kind::kHit ? 1 : 0;
    e.silhouetteMax_px = std::max(
        e.silhouetteMax_px, nearestRenderedAs(renderedHit, truth.columns, truth.rows, c, r, wanted, truth.stride));
  }
  return e;
}

}  // namespace globe
