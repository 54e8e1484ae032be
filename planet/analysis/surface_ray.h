#pragma once
// The exact planet seen through a pixel: the view ray intersected with the CPU reference surface
// (ElevationModel, double) by ray marching and bisection. This is the ground truth the screen-space
// error of a rendered frame is measured against (engine/render/frame_screen_error.h, docs/tradeoffs.md).
//
// Marching (on an ellipsoid the height is the ellipsoidal one, along the normal below the point):
// the ray enters the bounding sphere R + max elevation, then steps by the ray's height
// above the surface divided by a slope bound of that height along the ray (1 + L·R/r, with L a
// bound of the elevation's slope), so it cannot step through the surface; near the surface the step
// never drops below `minStepFraction` of the pixel footprint (t · pixel angle), the only place a
// feature narrower than that (a sub-pixel sliver) could be missed. A sign change is refined by
// bisection to `tolerance_m`.
#include "planet/camera/camera.h"
#include "planet/model/elevation_model.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace globe {

// Bound of |grad gradientNoise| in lattice units. The largest gradient found by sampling 4e6 random
// points and seeds was 3.17; 4 leaves a margin (an analytic bound, 14.7, would make marching ~4x
// slower for no measured difference).
inline constexpr double kGradientNoiseSlopeBound = 4.0;

// Bound of the elevation's slope (metres per metre of movement on the reference sphere): per layer
// sum amp_i · freq_i · kGradientNoiseSlopeBound (×2 for ridged), plus the modulation's chain rule.
double elevationSlopeBound(const gpu::ElevationParams& params);

struct SurfaceRayOptions {
  double tolerance_m = 1.0e-3;                                     // bisection stops when the bracket is this short
  double pixelAngle_rad = 1.0e-3;                                  // angle of one pixel (sets the minimum step)
  double minStepFraction = 0.05;                                   // minimum step, in pixel footprints
  uint32_t maxSteps = 200000;                                      // a ray that needs more is reported unresolved
  double maxDistance_m = std::numeric_limits<double>::infinity();  // sky beyond (segments, camera moves)
};

struct SurfaceRayHit {
  enum class Kind : uint8_t { kSky, kHit, kUnresolved };
  Kind kind = Kind::kSky;
  double distance_m = 0;     // along the (unit) ray, when Hit
  glm::dvec3 normal{0.0};    // unit surface normal at the hit, at the pixel's footprint scale
  uint32_t evaluations = 0;  // elevation evaluations spent
};

// What a ray stops at: the ground (collision meshes, placing bodies), or what a viewer sees (the sea's
// surface over lower ground on a planet with water: ElevationModel::visibleElevation_m).
enum class RaySurface { kGround, kVisible };

class SurfaceRayCaster {
 public:
  explicit SurfaceRayCaster(const ElevationModel& model, RaySurface surface = RaySurface::kGround);

  // `direction` must be unit length.
  SurfaceRayHit cast(const glm::dvec3& origin_m, const glm::dvec3& direction, const SurfaceRayOptions& options) const;

  double slopeBound() const { return slope_; }

 private:
  // Height of p above the surface below it (metres; negative inside the terrain).
  double heightAbove(const glm::dvec3& p) const {
    return model_.heightAboveTerrain_m(p, surface_ == RaySurface::kVisible);
  }
  // The reference surface's smallest radius of curvature (metres): a, or b^2 / a on an ellipsoid.
  static double curvatureRadius_m(const Ellipsoid& shape);
  glm::dvec3 normalAt(const glm::dvec3& p, double scale_m) const;

  const ElevationModel& model_;
  RaySurface surface_;
  double slope_ = 0;
  double minRadius_m_ = 0;
  double maxRadius_m_ = 0;
};

// Unit view ray through the centre of pixel (x, y) of a width x height image (row 0 at the top),
// matching Camera::projection() and rayDistanceFromDepth().
glm::dvec3 pixelRay(const Camera& camera, uint32_t width, uint32_t height, double x, double y);

// The truth for a grid of pixels: every `stride`-th pixel in x and y (the first at (stride/2,
// stride/2)), cast on `threads` threads (0 = hardware concurrency).
struct SurfaceTruth {
  uint32_t width = 0, height = 0;  // the image the pixels belong to
  uint32_t stride = 1;
  uint32_t columns = 0, rows = 0;   // samples
  std::vector<SurfaceRayHit> hits;  // rows x columns, row-major
  uint64_t evaluations = 0;
  double cast_ms = 0;

  uint32_t pixelX(uint32_t column) const { return column * stride + stride / 2; }
  uint32_t pixelY(uint32_t row) const { return row * stride + stride / 2; }
  const SurfaceRayHit& at(uint32_t column, uint32_t row) const { return hits[size_t(row) * columns + column]; }
};

// Rays stop at the visible surface (RaySurface::kVisible): the truth of what the renderer draws.
SurfaceTruth castSurfaceTruth(const ElevationModel& model, const Camera& camera, uint32_t width, uint32_t height,
                              uint32_t stride, unsigned threads = 0);

}  // namespace globe
