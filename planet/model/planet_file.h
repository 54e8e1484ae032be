#pragma once
// TOML planet files (toml++). The format, every key with units, range and default, is described in
// docs/planet-files.md; assets/planets/earthlike.toml is the reference example and the default planet.
//
//   name = "earthlike"          radius_m = 6371000.0      seed = 37786        sea_level_m = 0.0
//   [[layers]]                  # 1 to 8, evaluated in file order
//   name = "continents"         kind = "fbm"              # fbm | ridged | billow | craters
//   octaves = 4                 wavelength_m = 4.0e6      # or frequency_per_m, not both
//   lacunarity = 2.6            gain = 0.5                amplitude_m = 3500.0     offset_m = 0.0
//   modulated_by = "continents" modulation_low_m = 0.0   modulation_high_m = 2000.0
//   modulation_floor = 0.0      # only with modulated_by, which names an earlier layer
//   default_quality = "balanced"                          # fast | balanced | exact
//   [[colour_ramp]]             elevation_m = 0.0         colour = [0.45, 0.40, 0.28]   # 2 to 16 stops
//   [rock]                      slope_deg = 35.0          blend_deg = 10.0         colour = [...]
//   [snow]                      elevation_m = 4000.0      blend_m = 500.0          max_slope_deg = 50.0
//   [climate]                   equator_temperature_c = 27.0   lapse_rate_c_per_km = 6.5   ...
//   [[land_cover]]              name = "forest"  colour = [...]  temperature_c = [0.0, 25.0]   # 1 to 8
//                               moisture = [0.5, 1e30]  elevation_m = [...]  slope_deg = [0.0, 35.0]
//
// Nothing throws out of these functions: every problem (syntax, unknown key, wrong type, NaN/Inf,
// out of range, radius <= 0, too many octaves for double precision) is an Error with the file, the
// 1-based line and column of the offending key or value, and the key's path (e.g. "layers[1].gain").
#include <string>
#include <string_view>
#include <vector>

#include "planet/core/error.h"
#include "planet/model/planet_description.h"

namespace globe {

// The default planet of every command, relative to the source tree (and the installed data dir).
inline constexpr std::string_view kDefaultPlanetFile = "assets/planets/earthlike.toml";

// Every problem of a planet file at once (what `globe planet check` prints). A value that fails to
// read keeps its default and reading goes on, so one bad key does not hide the next; only a TOML
// syntax error stops early (toml++ does not recover), and is then the single error.
struct PlanetFileCheck {
  PlanetDescription planet;   // the description read; valid (and meaningful) only when ok()
  std::vector<Error> errors;  // sorted by line then column; empty when the file is valid
  bool ok() const { return errors.empty(); }
};
PlanetFileCheck checkPlanetFile(const std::string& path);
PlanetFileCheck checkPlanetToml(std::string_view text, std::string_view source_name);

// Reads and validates a planet file; the first problem (in file order) is the Error. The
// description's name defaults to the file's stem.
Result<PlanetDescription> loadPlanetFile(const std::string& path);

// Same, from text already in memory; `source_name` is the file name used in errors.
Result<PlanetDescription> parsePlanetToml(std::string_view text, std::string_view source_name);

}  // namespace globe
