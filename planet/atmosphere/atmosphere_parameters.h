#pragma once
// A planet's atmosphere for precomputed scattering [Bruneton & Neyret 2008]: a spherical shell from
// the planet's radius (the bottom) up `thickness_m`, holding Rayleigh molecules and Mie aerosols with
// exponential density profiles, and an ozone layer (absorption only) with a tent profile. Three
// wavelengths (680, 550, 440 nm: red, green, blue). The sun is a disc of `sun_angular_radius_deg`
// giving `sun_irradiance` at the top. Read from a planet file's [atmosphere] section
// (docs/planet-files.md); a planet without one has no atmosphere (black sky, unattenuated light).
//
// Earth's values are the defaults: those of the authors' 2017 reference implementation
// (docs/references.md), reduced to the three wavelengths.
#include "planet/core/error.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace globe {

struct AtmosphereParameters {
  double thickness_m = 60000.0;  // top radius = planet radius + thickness, (0, 1e6]
  // Rayleigh: scattering = extinction (no absorption); density exp(-altitude / scale height).
  glm::dvec3 rayleigh_scattering_per_m{5.802e-6, 13.558e-6, 33.1e-6};
  double rayleigh_scale_height_m = 8000.0;
  // Mie (aerosols, dust): scattering <= extinction (the rest absorbed); Cornette-Shanks phase with g.
  glm::dvec3 mie_scattering_per_m{3.996e-6, 3.996e-6, 3.996e-6};
  glm::dvec3 mie_extinction_per_m{4.44e-6, 4.44e-6, 4.44e-6};
  double mie_scale_height_m = 1200.0;
  double mie_g = 0.8;  // asymmetry, [0, 0.999)
  // Ozone: absorption at the layer's peak; density 1 at ozone_centre_m falling linearly to 0 at
  // ozone_centre_m +- ozone_half_width_m.
  glm::dvec3 ozone_absorption_per_m{0.650e-6, 1.881e-6, 0.085e-6};
  double ozone_centre_m = 25000.0;
  double ozone_half_width_m = 15000.0;
  glm::dvec3 sun_irradiance{1.474, 1.8504, 1.91198};  // at the top of the atmosphere (arbitrary units)
  double sun_angular_radius_deg = 0.2679;             // (0, 10]
  // The camera's exposure relative to the planet's own sunlight, (0, 1e4]: 1 shows a white surface
  // facing the sun above the air as white (scene value 1 before the display transform).
  double exposure = 1.0;
  double ground_albedo = 0.1;  // for light the ground sends back up, [0, 1]

  bool operator==(const AtmosphereParameters&) const = default;
};

// Every range and cross-field rule; each Error's field is "atmosphere.KEY". `planetRadius_m` bounds
// the thickness (at most the radius).
std::vector<Error> validateAtmosphere(const AtmosphereParameters& atmosphere, double planetRadius_m);

// A 64-bit hash of every parameter and the radius (the LUT cache file's key).
std::uint64_t atmosphereHash(const AtmosphereParameters& atmosphere, double planetRadius_m);

}  // namespace globe
