#include "planet/atmosphere/atmosphere_parameters.h"

#include "planet/core/finite_range.h"
#include "planet/core/hash.h"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <string>

namespace globe {
namespace {

// Coefficients per metre: Earth's largest is 3.3e-5; 1e-2 is a fog 100 m deep.
constexpr double kMaxCoefficient_per_m = 1e-2;

bool coefficientsInRange(const glm::dvec3& c) {
  return inRange(c.x, 0.0, kMaxCoefficient_per_m) && inRange(c.y, 0.0, kMaxCoefficient_per_m) &&
         inRange(c.z, 0.0, kMaxCoefficient_per_m);
}

}  // namespace

std::vector<Error> validateAtmosphere(const AtmosphereParameters& a, double planetRadius_m) {
  std::vector<Error> errors;
  auto fail = [&errors](const char* key, std::string message) {
    errors.push_back(Error::inField(std::string("atmosphere.") + key, std::move(message)));
  };
  const double maxThickness_m = std::min(1e6, std::isfinite(planetRadius_m) ? planetRadius_m : 1e6);
  if (!(inRange(a.thickness_m, 0.0, maxThickness_m) && a.thickness_m > 0.0))
    fail("thickness_m", fmt::format("must be > 0 and <= {:g} m (and at most the radius)", maxThickness_m));
  const std::string coefficient = fmt::format("must be three numbers in [0, {:g}] per metre", kMaxCoefficient_per_m);
  if (!coefficientsInRange(a.rayleigh_scattering_per_m)) fail("rayleigh_scattering_per_m", coefficient);
  if (!coefficientsInRange(a.mie_scattering_per_m)) fail("mie_scattering_per_m", coefficient);
  if (!coefficientsInRange(a.mie_extinction_per_m)) {
    fail("mie_extinction_per_m", coefficient);
  } else if (!(a.mie_scattering_per_m.x <= a.mie_extinction_per_m.x &&
               a.mie_scattering_per_m.y <= a.mie_extinction_per_m.y &&
               a.mie_scattering_per_m.z <= a.mie_extinction_per_m.z)) {
    fail("mie_extinction_per_m", "must be >= mie_scattering_per_m in every component");
  }
  if (!coefficientsInRange(a.ozone_absorption_per_m)) fail("ozone_absorption_per_m", coefficient);
  // A scale height below 10 m would need more integration steps than the tables take.
  if (!inRange(a.rayleigh_scale_height_m, 10.0, 1e6)) fail("rayleigh_scale_height_m", "must be within [10, 1e6] m");
  if (!inRange(a.mie_scale_height_m, 10.0, 1e6)) fail("mie_scale_height_m", "must be within [10, 1e6] m");
  if (!inRange(a.mie_g, 0.0, 0.999)) fail("mie_g", "must be within [0, 0.999]");
  if (!inRange(a.ozone_centre_m, 0.0, 1e6)) fail("ozone_centre_m", "must be within [0, 1e6] m");
  if (!(inRange(a.ozone_half_width_m, 0.0, 1e6) && a.ozone_half_width_m > 0.0))
    fail("ozone_half_width_m", "must be > 0 and <= 1e6 m");
  if (!(inRange(a.sun_irradiance.x, 0.0, 1e3) && inRange(a.sun_irradiance.y, 0.0, 1e3) &&
        inRange(a.sun_irradiance.z, 0.0, 1e3)))
    fail("sun_irradiance", "must be three numbers in [0, 1000]");
  if (!(inRange(a.sun_angular_radius_deg, 0.0, 10.0) && a.sun_angular_radius_deg > 0.0))
    fail("sun_angular_radius_deg", "must be > 0 and <= 10 degrees");
  if (!(inRange(a.exposure, 0.0, 1e4) && a.exposure > 0.0)) fail("exposure", "must be > 0 and <= 1e4");
  if (!inRange(a.ground_albedo, 0.0, 1.0)) fail("ground_albedo", "must be within [0, 1]");
  return errors;
}

std::uint64_t atmosphereHash(const AtmosphereParameters& a, double planetRadius_m) {
  const double values[] = {planetRadius_m,
                           a.thickness_m,
                           a.rayleigh_scattering_per_m.x,
                           a.rayleigh_scattering_per_m.y,
                           a.rayleigh_scattering_per_m.z,
                           a.rayleigh_scale_height_m,
                           a.mie_scattering_per_m.x,
                           a.mie_scattering_per_m.y,
                           a.mie_scattering_per_m.z,
                           a.mie_extinction_per_m.x,
                           a.mie_extinction_per_m.y,
                           a.mie_extinction_per_m.z,
                           a.mie_scale_height_m,
                           a.mie_g,
                           a.ozone_absorption_per_m.x,
                           a.ozone_absorption_per_m.y,
                           a.ozone_absorption_per_m.z,
                           a.ozone_centre_m,
                           a.ozone_half_width_m,
                           a.sun_irradiance.x,
                           a.sun_irradiance.y,
                           a.sun_irradiance.z,
                           a.sun_angular_radius_deg,
                           a.ground_albedo};
  // Chained through the one 64-bit mixer (planet/core/hash.h), bit patterns of the doubles.
  std::uint64_t h = 0x61746d6f73706865ull;
  for (double v : values) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof(bits));
    h = mix64(h ^ bits);
  }
  return h;
}

}  // namespace globe
