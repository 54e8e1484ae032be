#include "planet/atmosphere/atmosphere_reference.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace globe {
namespace {
constexpr int kSteps = 2000;
double weight(int i, int n) { return (i == 0 || i == n) ? 0.5 : 1.0; }
double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
}  // namespace

AtmosphereReference::AtmosphereReference(const AtmosphereParameters& atmosphere, double radius_m)
    : a_(atmosphere), bottom_(radius_m), top_(radius_m + atmosphere.thickness_m) {}

bool AtmosphereReference::rayHitsGround(double r, double mu) const {
  return mu < 0.0 && r * r * (mu * mu - 1.0) + bottom_ * bottom_ >= 0.0;
}

double AtmosphereReference::distanceToTop(double r, double mu) const {
  return std::max(-r * mu + std::sqrt(std::max(r * r * (mu * mu - 1.0) + top_ * top_, 0.0)), 0.0);
}

double AtmosphereReference::distanceToBoundary(double r, double mu) const {
  if (!rayHitsGround(r, mu)) return distanceToTop(r, mu);
  return std::max(-r * mu - std::sqrt(std::max(r * r * (mu * mu - 1.0) + bottom_ * bottom_, 0.0)), 0.0);
}

glm::dvec3 AtmosphereReference::extinction(double h) const {
  const double rayleigh = std::min(std::exp(-h / a_.rayleigh_scale_height_m), 1.0);
  const double mie = std::min(std::exp(-h / a_.mie_scale_height_m), 1.0);
  const double ozone = std::max(1.0 - std::abs(h - a_.ozone_centre_m) / a_.ozone_half_width_m, 0.0);
  return a_.rayleigh_scattering_per_m * rayleigh + a_.mie_extinction_per_m * mie + a_.ozone_absorption_per_m * ozone;
}

glm::dvec3 AtmosphereReference::transmittance(double r, double mu, double distance_m) const {
  const double dx = distance_m / kSteps;
  glm::dvec3 depth(0.0);
  for (int i = 0; i <= kSteps; ++i) {
    const double d = i * dx;
    depth += extinction(std::sqrt(d * d + 2.0 * r * mu * d + r * r) - bottom_) * weight(i, kSteps);
  }
  return glm::exp(-depth * dx);
}

void AtmosphereReference::singleScattering(double r, double mu, double muS, double nu, glm::dvec3& rayleigh,
                                           glm::dvec3& mie) const {
  constexpr int kSamples = 400;
  const double dx = distanceToBoundary(r, mu) / kSamples;
  const double sunRadius = a_.sun_angular_radius_deg * 3.14159265358979323846 / 180.0;
  rayleigh = mie = glm::dvec3(0.0);
  for (int i = 0; i <= kSamples; ++i) {
    const double d = i * dx;
    const double rd = std::clamp(std::sqrt(d * d + 2.0 * r * mu * d + r * r), bottom_, top_);
    const double muSd = std::clamp((r * muS + d * nu) / rd, -1.0, 1.0);
    // The sun's disc fading below the horizon, as in the model.
    const double sinH = bottom_ / rd, cosH = -std::sqrt(std::max(1.0 - sinH * sinH, 0.0));
    const double disc = smoothstep(-sinH * sunRadius, sinH * sunRadius, muSd - cosH);
    const glm::dvec3 t = transmittance(r, mu, d) * transmittanceToTop(rd, muSd) * disc * weight(i, kSamples);
    rayleigh += t * std::min(std::exp(-(rd - bottom_) / a_.rayleigh_scale_height_m), 1.0);
    mie += t * std::min(std::exp(-(rd - bottom_) / a_.mie_scale_height_m), 1.0);
  }
  rayleigh *= dx * a_.sun_irradiance * a_.rayleigh_scattering_per_m;
  mie *= dx * a_.sun_irradiance * a_.mie_scattering_per_m;
}

}  // namespace globe
