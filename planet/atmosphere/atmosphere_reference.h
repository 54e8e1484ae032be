#pragma once
// The atmosphere model's integrals in double, by brute force (fine trapezoid sums, no tables): the
// reference the GPU tables (engine/atmosphere/atmosphere_luts.h) are tested against. Same model
// as shaders/include/atmosphere_model.glsl: r from the planet centre, mu the cosine to the zenith.
#include "planet/atmosphere/atmosphere_parameters.h"

namespace globe {

class AtmosphereReference {
 public:
  AtmosphereReference(const AtmosphereParameters& atmosphere, double radius_m);

  double bottom_m() const { return bottom_; }
  double top_m() const { return top_; }
  bool rayHitsGround(double r, double mu) const;
  // Distance along (r, mu) to the ground if the ray hits it, else to the top.
  double distanceToBoundary(double r, double mu) const;
  // Transmittance along (r, mu) over `distance_m`.
  glm::dvec3 transmittance(double r, double mu, double distance_m) const;
  glm::dvec3 transmittanceToTop(double r, double mu) const { return transmittance(r, mu, distanceToTop(r, mu)); }
  // Single scattering towards (r, mu) from the sun at (mu_s, nu), without the phase functions:
  // what the scattering table's texel holds after the first order (Rayleigh rgb, Mie rgb).
  void singleScattering(double r, double mu, double muS, double nu, glm::dvec3& rayleigh, glm::dvec3& mie) const;

 private:
  double distanceToTop(double r, double mu) const;
  glm::dvec3 extinction(double altitude_m) const;

  AtmosphereParameters a_;
  double bottom_, top_;
};

}  // namespace globe
