#include "planet/analysis/surface_ray.h"

#include "planet/core/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "planet/core/gradient_noise.h"
#include "planet/elevation/crater_field.h"

namespace globe {

double elevationSlopeBound(const gpu::ElevationParams& params) {
  double slopes[GLOBE_MAX_ELEVATION_LAYERS] = {};
  double total = 0;
  for (gpu::uint l = 0; l < params.layer_count && l < GLOBE_MAX_ELEVATION_LAYERS; ++l) {
    const gpu::ElevationLayerParams& layer = params.layers[l];
    double frequency = layer.frequency, amplitude = layer.amplitude_m, slope = 0, size = 0;
    for (gpu::uint o = 0; o < layer.octaves; ++o) {
      slope += amplitude * frequency * kGradientNoiseSlopeBound;
      size += amplitude;
      frequency *= layer.lacunarity;
      amplitude *= layer.gain;
    }
    // Ridged: d(1 - |n|)^2 = -2 (1 - |n|) sign(n) dn, and 1 - |n| <= 1.
    if (layer.kind == GLOBE_LAYER_RIDGED) {
      slope *= 2.0;
    } else if (layer.kind == GLOBE_LAYER_CRATERS) {  // the field's own bounds, not the noise's
      slope *= kCraterFieldSlopeBound / kGradientNoiseSlopeBound;
      size *= -kCraterFieldMin;
    } else {
      size *= kGradientNoiseBound;
    }
    // value = sum · s(m(v_k)): d value = s · d sum + sum · s'(m) · m'(v_k) · d v_k, with s <= 1 and
    // s' <= (1 - floor) · 1.5 (smoothstep's steepest slope), m' = inv_range.
    if (layer.modulator >= 0 && layer.modulator < GLOBE_MAX_ELEVATION_LAYERS)
      slope += size * (1.0 - layer.modulation_floor) * 1.5 * layer.modulation_inv_range * slopes[layer.modulator];
    slopes[l] = slope;
    total += slope;
  }
  return total;
}

SurfaceRayCaster::SurfaceRayCaster(const ElevationModel& model, RaySurface surface)
    : model_(model),
      surface_(surface),
      slope_(elevationSlopeBound(model.params())),
      // On an ellipsoid the normal below a point turns fastest over the tightest curvature, b^2 / a.
      minRadius_m_(std::max(curvatureRadius_m(model.shape()) + model.bounds().min_m, 1e-3 * model.radius_m())),
      maxRadius_m_(model.radius_m() + std::max(model.bounds().max_m, 0.0)) {}

double SurfaceRayCaster::curvatureRadius_m(const Ellipsoid& shape) {
  if (shape.isSphere()) return shape.equatorialRadius_m();
  return shape.polarRadius_m() * shape.polarRadius_m() / shape.equatorialRadius_m();
}

glm::dvec3 SurfaceRayCaster::normalAt(const glm::dvec3& p, double scale_m) const {
  glm::dvec3 d = model_.shape().isSphere() ? glm::normalize(p) : model_.shape().normalBelow(p);
  glm::dvec3 helper = std::abs(d.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  glm::dvec3 e1 = glm::normalize(glm::cross(helper, d));
  glm::dvec3 e2 = glm::cross(d, e1);
  // Central differences over the pixel's footprint: the tangent plane a pixel sees, not the slope
  // of sub-pixel detail.
  double angle = scale_m / glm::length(p);
  auto surface = [&](const glm::dvec3& offset) { return model_.surfacePosition(glm::normalize(d + offset)); };
  glm::dvec3 du = surface(e1 * angle) - surface(-e1 * angle);
  glm::dvec3 dv = surface(e2 * angle) - surface(-e2 * angle);
  glm::dvec3 n = glm::cross(du, dv);
  double len = glm::length(n);
  return len > 0 ? n / len : d;
}

SurfaceRayHit SurfaceRayCaster::cast(const glm::dvec3& origin, const glm::dvec3& dir,
                                     const SurfaceRayOptions& options) const {
  SurfaceRayHit out;
  // Enter the bounding sphere (nothing outside it can be hit).
  double b = glm::dot(origin, dir);
  double c = glm::dot(origin, origin) - maxRadius_m_ * maxRadius_m_;
  double t = 0;
  if (c > 0) {
    double disc = b * b - c;
    if (b >= 0 || disc < 0) return out;  // moving away or missing the sphere: sky
    t = -b - std::sqrt(disc);
  }
  // |d/dt height| <= 1 + slope · R / r (the sub-surface point moves R/r as fast as the ray sideways).
  const double rate = 1.0 + slope_ * model_.radius_m() / minRadius_m_;
  double previous = t;
  double f = heightAbove(origin + t * dir);
  ++out.evaluations;
  if (f <= 0) {  // starts inside the terrain
    out.kind = SurfaceRayHit::Kind::kHit;
    out.distance_m = t;
    out.normal = normalAt(origin + t * dir, options.tolerance_m);
    return out;
  }
  for (uint32_t step = 0;; ++step) {
    if (step >= options.maxSteps) {
      out.kind = SurfaceRayHit::Kind::kUnresolved;
      return out;
    }
    glm::dvec3 p = origin + t * dir;
    if (glm::dot(p, p) > maxRadius_m_ * maxRadius_m_ && glm::dot(p, dir) > 0) return out;  // left: sky
    if (t > options.maxDistance_m) return out;                                             // past the segment
    double minStep = std::max(options.tolerance_m, options.minStepFraction * t * options.pixelAngle_rad);
    previous = t;
    t += std::max(f / rate, minStep);
    f = heightAbove(origin + t * dir);
    ++out.evaluations;
    if (f <= 0) break;
  }
  // Bisection: height(previous) > 0 >= height(t).
  double lo = previous, hi = t;
  while (hi - lo > options.tolerance_m && hi - lo > 1e-15 * hi) {
    double mid = 0.5 * (lo + hi);
    (heightAbove(origin + mid * dir) > 0 ? lo : hi) = mid;
    ++out.evaluations;
  }
  out.kind = SurfaceRayHit::Kind::kHit;
  out.distance_m = 0.5 * (lo + hi);
  out.normal = normalAt(origin + out.distance_m * dir, std::max(out.distance_m * options.pixelAngle_rad, 1e-3));
  return out;
}

glm::dvec3 pixelRay(const Camera& camera, uint32_t width, uint32_t height, double x, double y) {
  double tanY = std::tan(camera.verticalFov_rad * 0.5);
  double nx = (x + 0.5) / width * 2.0 - 1.0;
  double ny = (y + 0.5) / height * 2.0 - 1.0;
  // Pixel rows grow downwards (Vulkan clip space y is down, Camera::projection()).
  glm::dvec3 d = camera.forward + (nx * tanY * camera.aspect) * camera.right - (ny * tanY) * camera.up;
  return glm::normalize(d);
}

SurfaceTruth castSurfaceTruth(const ElevationModel& model, const Camera& camera, uint32_t width, uint32_t height,
                              uint32_t stride, unsigned threads) {
  auto start = std::chrono::steady_clock::now();
  SurfaceTruth truth;
  truth.width = width;
  truth.height = height;
  truth.stride = std::max(stride, 1u);
  truth.columns = (width + truth.stride - 1) / truth.stride;
  truth.rows = (height + truth.stride - 1) / truth.stride;
  truth.hits.resize(size_t(truth.columns) * truth.rows);
  SurfaceRayCaster caster(model, RaySurface::kVisible);  // what the renderer draws is the referee's subject
  SurfaceRayOptions options;
  options.pixelAngle_rad = camera.verticalFov_rad / double(height);
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<uint64_t> evaluations{0};
  // Rows are handed out one at a time: cost varies a lot between rows (sky vs grazing ground).
  parallelFor(truth.rows, 1, threads, [&](size_t firstRow, size_t endRow) {
    uint64_t local = 0;
    for (auto row = uint32_t(firstRow); row < endRow; ++row) {
      for (uint32_t column = 0; column < truth.columns; ++column) {
        uint32_t x = std::min(truth.pixelX(column), width - 1), y = std::min(truth.pixelY(row), height - 1);
        SurfaceRayHit hit = caster.cast(camera.position_m, pixelRay(camera, width, height, x, y), options);
        local += hit.evaluations;
        truth.hits[size_t(row) * truth.columns + column] = hit;
      }
    }
    evaluations += local;
  });
  truth.evaluations = evaluations;
  truth.cast_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return truth;
}

}  // namespace globe
