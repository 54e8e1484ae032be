#pragma once
// Land cover: what covers the ground (forest, desert, ice, ...), up to 8 classes per planet chosen by
// rules on a procedural climate (temperature from latitude and height, moisture from noise and the
// distance inland) and on the ground's height and slope. The `[climate]` and `[[land_cover]]` parts
// of a planet file (docs/planet-files.md). The payload kernel evaluates the masks per sample
// (shaders/include/land_cover.glsl); landCoverMasks is the reference it mirrors, in float.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "planet/core/error.h"
#include "shaders/include/land_cover_layout.h"

namespace globe {

inline constexpr int kMaxLandCoverClasses = GLOBE_MAX_LAND_COVER_CLASSES;
// An unbounded end of a class's range.
inline constexpr double kUnboundedRange = 1e30;

// The climate every class rule reads (the `[climate]` table). Temperatures in degrees Celsius.
struct Climate {
  double equator_temperature_c = 27.0;  // at sea level on the equator, [-300, 1000]
  double pole_temperature_c = -25.0;    // at sea level at the poles, [-300, 1000]
  double lapse_rate_c_per_km = 6.5;     // cooling with height above sea level, [0, 100]
  double temperature_noise_c = 4.0;     // amplitude of the temperature's noise, [0, 200]
  double moisture_base = 0.6;           // moisture before noise and drying, [-10, 10]
  double moisture_noise = 0.5;          // amplitude of the moisture's noise, [0, 10]
  // Moisture lost inland: 1 per this many metres the first (continental) layer stands above sea
  // level; the continental layer rises away from its coasts, so its height stands for the distance
  // to the sea without a search for the nearest coast. [1, 1e7]
  double inland_drying_m = 2000.0;
  double noise_wavelength_m = 2.0e6;  // wavelength of both noises' first octave, (0, 1e9]
  // Width of every class's soft edges, per criterion (> 0).
  double temperature_blend_c = 4.0;
  double moisture_blend = 0.1;
  double elevation_blend_m = 40.0;
  double slope_blend_deg = 6.0;

  bool operator==(const Climate&) const = default;
};

// One class: where it grows (every range must hold) and what it looks like.
struct LandCoverClass {
  std::string name;  // unique within the planet, [a-z0-9_-]+
  double temperature_min_c = -kUnboundedRange, temperature_max_c = kUnboundedRange;
  double moisture_min = -kUnboundedRange, moisture_max = kUnboundedRange;
  double elevation_min_m = -kUnboundedRange, elevation_max_m = kUnboundedRange;  // above sea level
  double slope_min_deg = 0.0, slope_max_deg = 90.0;
  glm::vec3 colour = glm::vec3(0.2f);  // linear RGB albedo, the class's mean colour
  // The class's tiled detail texture: procedural (contrast of its grain, [0, 1]) unless `texture`
  // names a PNG (a path relative to the planet file), whose colours are taken relative to their mean.
  double detail_contrast = 0.35;
  std::string texture;

  bool operator==(const LandCoverClass&) const = default;
};

struct LandCover {
  Climate climate;
  std::vector<LandCoverClass> classes;  // 0 = no land cover (the colour ramp colours the ground)

  bool enabled() const { return !classes.empty(); }
  bool operator==(const LandCover&) const = default;
};

// Every problem, each an Error with `field` set ("land_cover[2].moisture", "climate.lapse_rate_c_per_km").
void appendLandCoverErrors(const LandCover& cover, std::vector<Error>& errors);

// The shaders' struct for a valid land cover on a planet of `radius_m`, seeded from `planet_seed`.
gpu::LandCoverParams packLandCover(const LandCover& cover, double radius_m, std::uint64_t planet_seed,
                                   double sea_level_m);

// The 8 mask bytes of one sample (summing to 255; zero past class_count).
using LandCoverMasks = std::array<std::uint8_t, kMaxLandCoverClasses>;

// What the rules read at one sample.
struct LandCoverSite {
  glm::dvec3 unit_direction{0.0, 0.0, 1.0};
  double elevation_m = 0.0;    // the drawn ground's elevation above radius_m
  double first_layer_m = 0.0;  // the planet's first layer's value (ElevationModel::firstLayer_m)
  double cos_slope = 1.0;      // cosine of the angle between the surface normal and the vertical
};

// The climate at a sample (reference of land_cover.glsl).
struct ClimateSample {
  float temperature_c = 0.0f;
  float moisture = 0.0f;
};
ClimateSample climateAt(const gpu::LandCoverParams& params, const LandCoverSite& site);

// The reference evaluation (see shaders/include/land_cover_layout.h); requires class_count > 0.
LandCoverMasks landCoverMasks(const gpu::LandCoverParams& params, const LandCoverSite& site);

// The albedo of a sample's masks: sum(mask_i / 255 * colour_i), linear RGB.
glm::vec3 landCoverAlbedo(const gpu::LandCoverParams& params, const LandCoverMasks& masks);

}  // namespace globe
