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
glm::dvec3 rgb(const gpu::TerrainVec4& v) { return {v.x, v.y, v.z}; }

// Calls `atAltitude(altitude_m, step_m)` at the midpoints of kSunSteps equal steps along the ray
// (r_m from the centre, mu the cosine to the zenith) up to the top of the air (radius top_m), the
// altitudes above the ground of radius bottom_m: the haze's optical depths in double. (The
// AtmosphereReference's 2000 trapezoid steps over the double parameters are the tests' reference;
// these follow the packed parameters the tables were computed from, eight rays a frame.)
template <class F>
void alongRayToTop(double r_m, double mu, double bottom_m, double top_m, F&& atAltitude) {
  const double length = -r_m * mu + std::sqrt(std::max(r_m * r_m * (mu * mu - 1.0) + top_m * top_m, 0.0));
  const double step = length / kSunSteps;
  for (int i = 0; i < kSunSteps; ++i) {
    const double t = (i + 0.5) * step;
    atAltitude(std::sqrt(r_m * r_m + t * (2.0 * r_m * mu + t)) - bottom_m, step);
  }
}

// The phase functions of shaders/include/atmosphere_phase.glsl (per steradian), mirrored.
double rayleighPhase(double nu) { return 3.0 / (16.0 * kPi) * (1.0 + nu * nu); }
double cornetteShanksPhase(double nu, double g) {
  const double k = 3.0 / (8.0 * kPi) * (1.0 - g * g) / (2.0 + g * g);
  return k * (1.0 + nu * nu) / std::pow(std::max(1.0 + g * g - 2.0 * g * nu, 1e-6), 1.5);
}

// What the haze (terrain_haze.glsl's formula) sends down a ray from the top of the air to the ground
// at `bottom_m` along unit `v` (against the local vertical `up`): the sky the sea reflects there.
// The Rayleigh and Mie optical depths by a midpoint sum in double, `frame`'s haze constants set.
glm::dvec3 hazeSkyRadiance(const gpu::TerrainFrame& frame, const glm::dvec3& sunAloft, double bottom_m,
                           const glm::dvec3& up, const glm::dvec3& v, const glm::dvec3& sun) {
  double depthR = 0.0, depthM = 0.0;
  alongRayToTop(bottom_m, glm::dot(up, v), bottom_m, frame.hazeSun.w, [&](double h, double step) {
    depthR += step * std::exp(-h * frame.hazeRayleigh.w);
    depthM += step * std::exp(-h * frame.hazeMie.w);
  });
  const glm::dvec3 rayleigh = rgb(frame.hazeRayleigh) * depthR, mie = rgb(frame.hazeMie) * depthM;
  const glm::dvec3 mieScattered = rgb(frame.hazeMieScattering) * depthM;
  const double nu = glm::dot(v, sun);
  const glm::dvec3 scattered = sunAloft * rayleigh * rayleighPhase(nu) +
                               rgb(frame.hazeSun) * mieScattered * cornetteShanksPhase(nu, frame.hazeMieScattering.w) +
                               rgb(frame.hazeSky) * (rayleigh + mieScattered);
  return scattered / glm::max(rayleigh + mie, glm::dvec3(1e-30)) * (1.0 - glm::exp(-(rayleigh + mie)));
}

// The sky straight up and just above the horizon (mu 0.02, averaged over four azimuths, as
// atmosphere_view.comp's for `full`) over the ground below the camera, into frame.skyZenith and
// skyHorizon: the sea of the pipelines without the atmosphere's light reflects them.
void writeHazeSky(gpu::TerrainFrame& frame, const glm::dvec3& sunAloft, double bottom_m, const glm::dvec3& up,
                  const glm::dvec3& sun) {
  const glm::dvec3 east = glm::normalize(std::abs(up.z) < 0.9 ? glm::cross(glm::dvec3(0.0, 0.0, 1.0), up)
                                                              : glm::cross(glm::dvec3(1.0, 0.0, 0.0), up));
  const glm::dvec3 north = glm::cross(up, east);
  const double mu = 0.02;
  glm::dvec3 horizon(0.0);
  for (int k = 0; k < 4; ++k) {
    const double a = k * 0.5 * kPi;
    horizon +=
        0.25 * hazeSkyRadiance(frame, sunAloft, bottom_m, up,
                               mu * up + std::sqrt(1.0 - mu * mu) * (std::cos(a) * east + std::sin(a) * north), sun);
  }
  const glm::dvec3 zenith = hazeSkyRadiance(frame, sunAloft, bottom_m, up, up, sun);
  frame.skyZenith = vec4(zenith.x, zenith.y, zenith.z, 0.0);
  frame.skyHorizon = vec4(horizon.x, horizon.y, horizon.z, 0.0);
}

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
  const glm::dvec3 rayleigh = rgb(a.rayleigh), mie = rgb(a.mieExtinction), ozone = rgb(a.ozone);
  glm::dvec3 depth(0.0);
  alongRayToTop(r_m, mu, bottom, top, [&](double altitude, double step) {
    const double ozoneDensity = std::max(1.0 - std::abs(altitude - a.ozone.w) / a.misc.x, 0.0);
    depth += step * (rayleigh * std::exp(-altitude / a.rayleigh.w) + mie * std::exp(-altitude / a.mieScattering.w) +
                     ozone * ozoneDensity);
  });
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
  frame.hazeRayleigh = frame.hazeMie = frame.hazeMieScattering = frame.hazeSun = frame.hazeSky = frame.hazeGround =
      frame.hazeSunAloft = {0.0f, 0.0f, 0.0f, 0.0f};
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
  // The Rayleigh part scatters the sunlight of its own heights, whiter than the ground's at a low sun:
  // its mean height over the column between the ground and the camera, at most the scale height
  // (the sky's rays, to the top, take the scale height).
  const double scale = a->rayleigh.w, column = std::max(r - a->radii.x, 1.0);
  const double mean = scale - column * std::exp(-column / scale) / -std::expm1(-column / scale);
  auto sunlightAt = [&](double height_m) {
    return exposure * rgb(a->sun) * hazeSunTransmittance(*a, a->radii.x + height_m, muS);
  };
  const glm::dvec3 aloft = sunlightAt(mean);
  frame.hazeSunAloft = vec4(aloft.x, aloft.y, aloft.z, 0.0);
  const glm::dvec3 skySun = sunlightAt(scale);
  writeHazeSky(frame, skySun, a->radii.x, up, glm::normalize(sun));
}

}  // namespace globe
