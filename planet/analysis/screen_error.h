#pragma once
// Screen-space geometric error of a rendered frame against the exact planet (docs/tradeoffs.md):
// the read-back depth of each sampled pixel against the CPU ray cast of the same pixel
// (planet/analysis/surface_ray.h).
//
// Per sampled pixel where both hit the ground:
//   metres: |rendered distance − true distance| along the view ray;
//   pixels: the rendered point P and its projection Q onto the true surface's tangent plane at the
//           true hit (the nearest true surface point, at the pixel's scale) are both projected;
//           their angular separation seen from the camera, in pixels. A pure error along the ray
//           (looking straight down at a flat plane) is invisible and counts 0 px; the same height
//           error seen edge-on at the horizon counts fully.
// Silhouette: samples where one says ground and the other sky; their count, and the largest distance
// (in pixels) from such a sample to the nearest sample where the rendered image has the true answer
// (how far the rendered silhouette is from the true one; a multiple of the sampling stride).
#include "planet/analysis/surface_ray.h"
#include "planet/camera/camera.h"

#include <cstdint>

namespace globe {

struct ScreenError {
  uint32_t samples = 0;                       // sampled pixels
  uint32_t bothHit = 0;                       // ... where both the render and the truth hit the ground
  uint32_t unresolved = 0;                    // truth rays that exceeded the step limit (left out)
  double p50_px = 0, p95_px = 0, max_px = 0;  // nearest-rank percentiles over bothHit
  double p50_m = 0, p95_m = 0, max_m = 0;
  uint32_t silhouetteMismatches = 0;  // ground in one, sky in the other
  double silhouetteMax_px = 0;        // worst distance to the nearest sample rendered correctly
};

// From per-pixel rendered ray distances (+inf = sky), width x height row-major (the read-back frame
// overload is engine/render/frame_screen_error.h; tests inject a known error here).
ScreenError measureScreenError(const SurfaceTruth& truth, const std::vector<double>& renderedDistance_m,
                               const Camera& camera);

}  // namespace globe
