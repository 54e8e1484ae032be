#include "engine/render/shadow_cascades.h"

#include <algorithm>
#include <cmath>

namespace globe {
namespace {

// The finest cascade's ground radius in heights of the camera above the ground, and its least.
constexpr double kFirstRadiusPerHeight = 2.5;
constexpr double kFirstRadiusMin_m = 200.0;
// The sun this far below the camera's horizon (sine of 5 degrees) lights no relief near it.
constexpr double kSunBelowHorizonSin = -0.0872;

struct LightBasis {
  glm::dvec3 x, y, z;  // z towards the sun; x horizontal at the cascade's centre
};

LightBasis lightBasis(const glm::dvec3& sun, const glm::dvec3& up) {
  glm::dvec3 x = glm::cross(up, sun);
  if (glm::length(x) < 1e-9) x = glm::cross(std::abs(sun.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), sun);
  x = glm::normalize(x);
  return {x, glm::cross(sun, x), sun};
}

// Bounds, in the light's axes, of the ground within `radius_m` of `centre` between radii lo and hi.
struct LightBounds {
  glm::dvec3 lo{1e300}, hi{-1e300};
  void add(const glm::dvec3& p, const LightBasis& l) {
    const glm::dvec3 c(glm::dot(p, l.x), glm::dot(p, l.y), glm::dot(p, l.z));
    lo = glm::min(lo, c);
    hi = glm::max(hi, c);
  }
};

LightBounds groundBounds(const glm::dvec3& centreUp, double radius_m, glm::dvec2 band, const LightBasis& l) {
  const glm::dvec3 e1 = l.x, e2 = glm::normalize(glm::cross(centreUp, e1));
  LightBounds b;
  constexpr int kAzimuths = 24;
  for (int k = 0; k <= kAzimuths; ++k) {
    const double a = 2.0 * M_PI * k / kAzimuths;
    const glm::dvec3 dir = k == kAzimuths
                               ? centreUp
                               : glm::normalize(centreUp * band.x + (std::cos(a) * e1 + std::sin(a) * e2) * radius_m);
    b.add(dir * band.x, l);
    b.add(dir * band.y, l);
  }
  return b;
}

ShadowCascade fitCascade(const ShadowView& v, const glm::dvec3& centreUp, double radius_m) {
  const LightBasis l = lightBasis(v.sun, centreUp);
  // The receivers' relief band: the ground under the camera, +-30 % of the radius and 200 m.
  const double band_m = 0.3 * radius_m + 200.0;
  const double lo = std::min(v.groundRadius_m, std::max(v.terrainRadii_m.x, v.groundRadius_m - band_m));
  const double hi = std::max(v.groundRadius_m, std::min(v.terrainRadii_m.y, v.groundRadius_m + band_m));
  const LightBounds b = groundBounds(centreUp, radius_m, {lo, hi}, l);
  const double res = double(v.resolution);
  const glm::dvec2 half(0.5 * (b.hi.x - b.lo.x), 0.5 * (b.hi.y - b.lo.y));
  const glm::dvec2 texel = 2.0 * half / res;
  // The box's centre on the texel grid (planet-fixed light axes): whole texels as the camera moves.
  const glm::dvec2 centre = glm::round(0.5 * glm::dvec2(b.lo.x + b.hi.x, b.lo.y + b.hi.y) / texel) * texel;
  // Towards the sun, room for casters beyond the receivers (where depthClamp is missing); away from
  // it, nothing behind the receivers matters.
  const double zNear = b.hi.z + std::min(2.0 * radius_m, 100000.0) + 10000.0;
  const double zFar = b.lo.z - 2.0 * std::max(texel.x, texel.y);
  const double depth = zNear - zFar;
  const glm::dvec3 cam = v.camera->position_m;
  ShadowCascade c;
  glm::dmat4& m = c.clipFromCamera;
  for (int axis = 0; axis < 3; ++axis)
    m[axis] = glm::dvec4(l.x[axis] / half.x, l.y[axis] / half.y, -l.z[axis] / depth, 0.0);
  m[3] = glm::dvec4((glm::dot(cam, l.x) - centre.x) / half.x, (glm::dot(cam, l.y) - centre.y) / half.y,
                    (zNear - glm::dot(cam, l.z)) / depth, 1.0);
  c.radius_m = radius_m;
  c.texel_m = std::max(texel.x, texel.y);
  c.depth_m = depth;
  return c;
}

// The finest cascade's radius: 2.5 x the height (at least 200 m), up to a power of two, so that radii
// (and so texel sizes) change in steps as the camera climbs, not every frame, and the shadows' edges
// do not crawl.
double firstRadius_m(double height_m) {
  return std::exp2(std::ceil(std::log2(std::max(kFirstRadiusPerHeight * height_m, kFirstRadiusMin_m))));
}

// Whether a cascade of `radius_m` is drawn (beyond a quarter of the radius a flat box no longer fits).
bool cascadeFits(double radius_m, double groundRadius_m) { return radius_m <= 0.25 * groundRadius_m; }

}  // namespace

bool sunAboveShadowLimit(const glm::dvec3& up, const glm::dvec3& sun) {
  return glm::dot(up, sun) >= kSunBelowHorizonSin;
}

double shadowReach_m(double height_m, double groundRadius_m, bool sunUp) {
  if (height_m > kShadowMaxHeight_m || !sunUp) return 0.0;
  double reach_m = 0.0;
  double radius_m = firstRadius_m(std::max(height_m, 1.0));
  for (uint32_t k = 0; k < kShadowCascades && cascadeFits(radius_m, groundRadius_m);
       ++k, radius_m *= kShadowCascadeRatio)
    reach_m = 1.5 * radius_m;
  return reach_m;
}

ShadowCascades fitShadowCascades(const ShadowView& v) {
  ShadowCascades out;
  const Camera& camera = *v.camera;
  const glm::dvec3 up = glm::normalize(camera.position_m);
  const double height_m = std::max(glm::length(camera.position_m) - v.groundRadius_m, 1.0);
  if (height_m > kShadowMaxHeight_m || !sunAboveShadowLimit(up, v.sun)) return out;
  // The patches lie ahead of the camera: half their radius along the view's horizontal direction.
  glm::dvec3 ahead = camera.forward - up * glm::dot(camera.forward, up);
  ahead = glm::length(ahead) > 1e-6 ? glm::normalize(ahead) : glm::dvec3(0.0);
  double radius_m = firstRadius_m(height_m);
  for (; out.count < kShadowCascades && cascadeFits(radius_m, v.groundRadius_m); radius_m *= kShadowCascadeRatio) {
    const glm::dvec3 centreUp = glm::normalize(up * v.groundRadius_m + ahead * (0.5 * radius_m));
    out.cascades[out.count++] = fitCascade(v, centreUp, radius_m);
  }
  return out;
}

}  // namespace globe
