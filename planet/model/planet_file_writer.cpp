#include "planet/model/planet_file_writer.h"

#include "planet/atmosphere/atmosphere_toml.h"
#include "planet/core/planet_toml_reader.h"
#include "planet/sources/imagery_toml.h"
#include "planet/surface/land_cover_toml.h"
#include "planet/vectors/vector_toml.h"

#include <fmt/format.h>
#include <cassert>
#include <iterator>

namespace globe {
namespace {

// fmt's "{}" is the shortest text that parses back to the same double ("6371000", "0.64", "1e+30").
std::string number(double v) { return fmt::format("{}", v); }
std::string colour(const glm::vec3& c) { return fmt::format("[{}, {}, {}]", c.x, c.y, c.z); }

}  // namespace

std::string formatPlanetToml(const PlanetDescription& planet) {
  assert(validatePlanet(planet).ok());
  std::string out;
  auto line = std::back_inserter(out);
  // A sphere keeps radius_m (files written before ellipsoids read the same); an ellipsoid is a shape.
  const std::string shape = planet.flattening == 0.0
                                ? fmt::format("radius_m = {}", number(planet.radius_m))
                                : fmt::format("shape = {{ equatorial_radius_m = {}, flattening = {} }}",
                                              number(planet.radius_m), number(planet.flattening));
  fmt::format_to(line,
                 "name = {}\n{}\nseed = {}\nsea_level_m = {}\nsurface_gravity_m_s2 = {}\n"
                 "default_quality = \"{}\"\n",
                 tomlQuoted(planet.name), shape, planet.seed, number(planet.sea_level_m),
                 number(planet.surface_gravity_m_s2), qualityPresetName(planet.default_quality));
  for (const ElevationLayer& l : planet.layers) {
    fmt::format_to(line,
                   "\n[[layers]]\nname = {}\nkind = \"{}\"\noctaves = {}\nwavelength_m = {}\nlacunarity = {}\n"
                   "gain = {}\namplitude_m = {}\noffset_m = {}\n",
                   tomlQuoted(l.name), layerKindName(l.kind), l.octaves, number(l.wavelength_m), number(l.lacunarity),
                   number(l.gain), number(l.amplitude_m), number(l.offset_m));
    if (l.modulated_by >= 0) {
      fmt::format_to(line, "modulated_by = {}\nmodulation_low_m = {}\nmodulation_high_m = {}\nmodulation_floor = {}\n",
                     tomlQuoted(planet.layers[static_cast<std::size_t>(l.modulated_by)].name),
                     number(l.modulation_low_m), number(l.modulation_high_m), number(l.modulation_floor));
    }
  }
  for (const ElevationSource& src : planet.sources) {
    fmt::format_to(line,
                   "\n[[sources]]\npath = {}\nnodata = \"{}\"\namplify = {}\npriority = {}\nvertical_scale = {}\n"
                   "vertical_offset_m = {}\n",
                   tomlQuoted(src.path), noDataModeName(src.nodata), src.amplify ? "true" : "false", src.priority,
                   number(src.vertical_scale), number(src.vertical_offset_m));
    if (src.blend_m >= 0.0) fmt::format_to(line, "blend_m = {}\n", number(src.blend_m));
  }
  out += formatImageryToml(planet.imagery);
  out += formatVectorsToml(planet.vectors);
  const ColourRamp& ramp = planet.colour_ramp;
  for (const ColourRampStop& s : ramp.stops) {
    fmt::format_to(line, "\n[[colour_ramp]]\nelevation_m = {}\ncolour = {}\n", number(s.elevation_m), colour(s.colour));
  }
  fmt::format_to(line, "\n[rock]\nslope_deg = {}\nblend_deg = {}\ncolour = {}\n", number(ramp.rock_slope_deg),
                 number(ramp.rock_blend_deg), colour(ramp.rock_colour));
  if (ramp.snow) {
    fmt::format_to(line, "\n[snow]\nelevation_m = {}\nblend_m = {}\nmax_slope_deg = {}\ncolour = {}\n",
                   number(ramp.snow_elevation_m), number(ramp.snow_blend_m), number(ramp.snow_max_slope_deg),
                   colour(ramp.snow_colour));
  }
  if (planet.water.enabled) {
    fmt::format_to(line, "\n[water]\nshallow_colour = {}\ndeep_colour = {}\ndepth_scale_m = {}\n",
                   colour(planet.water.shallow_colour), colour(planet.water.deep_colour),
                   number(planet.water.depth_scale_m));
  }
  out += formatLandCoverToml(planet.land_cover);
  if (planet.atmosphere) out += formatAtmosphereToml(*planet.atmosphere);
  return out;
}

}  // namespace globe
