#include "engine/render/terrain_haze.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace globe {
namespace {

constexpr int kSunSteps = 256;
constexpr double kPi = 3.14159265358979323846;

gpu::TerrainVec4 vec4(double x, double y, double z, double w) { return {float(x), float(y), float(z), float(w)}; }
glm::dvec3 rgb(const gpu::AtmosphereVec4& v) { return {v.x, v.y, v.z}; }

}  // namespace

glm::dvec3 atmosphereCamera(const Ellipsoid& shape, double radius_m, const glm::dvec3& camera_m) {
  if (shape.isSphere()) return camera_m;
  const GeodeticPoint above = shape.geodeticAbove(camera_m, radius_m);
  return Ellipsoid::normalAt(above) * (radius_m + above.height_m);
}

glm::dvec3 hazeSunTransmittance(const gpu::AtmosphereGpu& a, double r_m, double mu) {
  const double bottom = a.radii.x, top = a.radii.y;
  // The ray meets the planet: below the horizon.
  if (mu < 0.0 && r_m * r_m * (mu * mu - 1.0) + bottom * bottom >= 0.0) return glm::dvec3(0.0);
  const double length = -r_m * mu + std::sqrt(std::max(r_m * r_m * (mu * mu - 1.0) + top * top, 0.0));
  const double step = length / kSunSteps;
  const glm::dvec3 rayleigh = rgb(a.rayleigh), mie = rgb(a.mieExtinction), ozone = rgb(a.ozone);
  glm::dvec3 depth(0.0);
  for (int i = 0; i < kSunSteps; ++i) {
    const double t = (i + 0.5) * step;
    const double altitude = std::sqrt(r_m * r_m + t * (2.0 * r_m * mu + t)) - bottom;
    const double ozoneDensity = std::max(1.0 - std::abs(altitude - a.ozone.w) / a.misc.x, 0.0);
    depth += step * (rayleigh * std::exp(-altitude / a.rayleigh.w) + mie * std::exp(-altitude / a.mieScattering.w) +
                     ozone * ozoneDensity);
  }
  return glm::exp(-depth);
}

glm::dvec3 hazeSkyIrradiance(const float* irradiance, double muS) {
  // Row 0 is the bottom radius; along it mu_s * 0.5 + 0.5 spans the texel centres (atmIrradianceUv).
  const double p = std::clamp(muS * 0.5 + 0.5, 0.0, 1.0) * double(GLOBE_IRRADIANCE_W - 1);
  const int i0 = std::min(int(p), GLOBE_IRRADIANCE_W - 2);
  const double f = p - double(i0);
  glm::dvec3 e;
  for (int c = 0; c < 3; ++c) e[c] = (1.0 - f) * irradiance[4 * i0 + c] + f * irradiance[4 * (i0 + 1) + c];
  return e;
}

void writeHazeConstants(gpu::TerrainFrame& frame, const gpu::AtmosphereGpu* a, const float* irradiance,
                        const glm::dvec3& cameraFromCentre_m, const glm::dvec3& sun) {
  frame.hazeRayleigh = frame.hazeMie = frame.hazeMieScattering = frame.hazeSun = frame.hazeSky =
      frame.hazeGround = {0.0f, 0.0f, 0.0f, 0.0f};
  if (!a) return;
  const double r = glm::length(cameraFromCentre_m);
  const glm::dvec3 up = r > 0.0 ? cameraFromCentre_m / r : glm::dvec3(0.0, 0.0, 1.0);
  const double muS = glm::dot(up, glm::normalize(sun)), exposure = a->misc.z;
  const glm::dvec3 direct = rgb(a->sun) * hazeSunTransmittance(*a, a->radii.x, muS);
  const glm::dvec3 sunlight = exposure * direct;
  glm::dvec3 sky(0.0);
  if (irradiance) {
    sky = hazeSkyIrradiance(irradiance, muS);
    const glm::dvec3 ground = double(a->misc.y) * (sky + direct * std::max(muS, 0.0));
    const glm::dvec3 average = 0.5 * (sky + ground) / kPi;
    frame.hazeSky = vec4(exposure * average.x, exposure * average.y, exposure * average.z, 0.0);
  }
  frame.hazeRayleigh = vec4(a->rayleigh.x, a->rayleigh.y, a->rayleigh.z, 1.0 / a->rayleigh.w);
  frame.hazeMie = vec4(a->mieExtinction.x, a->mieExtinction.y, a->mieExtinction.z, 1.0 / a->mieScattering.w);
  frame.hazeMieScattering = vec4(a->mieScattering.x, a->mieScattering.y, a->mieScattering.z, a->mieExtinction.w);
  frame.hazeSun = vec4(sunlight.x, sunlight.y, sunlight.z, a->radii.y);
  const glm::dvec3 skyLight = exposure * sky / kPi;
  frame.hazeGround = vec4(skyLight.x, skyLight.y, skyLight.z, 1.0);
}

}  // namespace globe
