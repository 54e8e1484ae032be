#pragma once
// Surface colour of a planet by elevation and slope: the `[[colour_ramp]]`, `[rock]` and `[snow]`
// parts of a planet file (docs/planet-files.md). Plain data; packColourRamp turns it into the
// fixed-size struct the shaders read (shaders/include/colour_ramp_layout.h) and rampColour is the
// reference evaluation (used by `globe planet export --png` and mirrored by shaders).
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "planet/core/error.h"
#include "shaders/include/colour_ramp_layout.h"

namespace globe {

inline constexpr int kMaxColourStops = GLOBE_MAX_COLOUR_STOPS;

struct ColourRampStop {
  double elevation_m = 0.0;         // elevation above radius_m, metres, [-1e7, 1e7]
  glm::vec3 colour = glm::vec3(0);  // linear RGB, each in [0, 1]

  bool operator==(const ColourRampStop&) const = default;
};

// The ramp used when a planet file has none: an Earth-like ocean / lowland / highland / peak ramp
// over -6000 .. +5000 m (the terrain renderer has the same idea).
std::vector<ColourRampStop> defaultColourRampStops();

struct ColourRamp {
  // 2 .. kMaxColourStops stops, elevations strictly increasing; colours between stops are
  // interpolated linearly, outside the end stops they are clamped.
  std::vector<ColourRampStop> stops = defaultColourRampStops();
  // Rock on steep ground: none below rock_slope_deg - rock_blend_deg / 2, full above + blend / 2.
  double rock_slope_deg = 35.0;  // degrees from horizontal, [0, 90]
  double rock_blend_deg = 10.0;  // degrees, [0, 90]
  glm::vec3 rock_colour = glm::vec3(0.22f, 0.20f, 0.18f);
  // Snow above snow_elevation_m (full at + snow_blend_m) where the slope is at most max_slope_deg.
  bool snow = false;                 // true when the file has a [snow] table
  double snow_elevation_m = 4000.0;  // metres, [-1e7, 1e7]
  double snow_blend_m = 500.0;       // metres, [0, 1e7]
  double snow_max_slope_deg = 50.0;  // degrees, [0, 90]
  glm::vec3 snow_colour = glm::vec3(0.90f, 0.92f, 0.95f);

  bool operator==(const ColourRamp&) const = default;
};

// The sea: a water surface drawn at sea_level_m over everything below it (the `[water]` table).
// Its colour is tinted by the depth of the ground beneath, shallow_colour at the shore to
// deep_colour far down (1 - exp(-depth / depth_scale_m) of the way), lit by the sun, with the sky's
// Fresnel reflection and a sun glint.
struct Water {
  bool enabled = false;                                          // true when the file has a [water] table
  glm::vec3 shallow_colour = glm::vec3(0.020f, 0.110f, 0.130f);  // linear RGB
  glm::vec3 deep_colour = glm::vec3(0.004f, 0.016f, 0.045f);     // linear RGB
  double depth_scale_m = 25.0;                                   // metres, (0, 1e5]

  bool operator==(const Water&) const = default;
};

// The colour of the sea over ground depth_m below sea level (> 0): the renderer's tint,
// mix(shallow_colour, deep_colour, 1 - exp(-depth_m / depth_scale_m)), unlit.
glm::vec3 seaColour(const Water& water, double depth_m);

// Every problem with the ramp, each an Error with `field` set (e.g. "colour_ramp[2].elevation_m").
void appendColourRampErrors(const ColourRamp& ramp, std::vector<Error>& errors);
// Every problem with the water ("water.depth_scale_m", ...); nothing when it is not enabled.
void appendWaterErrors(const Water& water, std::vector<Error>& errors);

// Packs a valid ramp (appendColourRampErrors adds nothing) into the shaders' struct.
gpu::ColourRampParams packColourRamp(const ColourRamp& ramp);

// The reference evaluation (see shaders/include/colour_ramp_layout.h): linear RGB at elevation
// `elevation_m` (metres above radius_m) on ground whose normal makes cos_slope with the vertical.
glm::vec3 rampColour(const gpu::ColourRampParams& ramp, double elevation_m, double cos_slope);

}  // namespace globe
