#pragma once
// TOML planet files (toml++). The format, every key with units, range and default, is described in
// docs/elevation.md; assets/planets/earthlike.toml is the reference example and the default planet.
//
//   name = "earthlike"          radius_m = 6371000.0      seed = 20180302     sea_level_m = 0.0
//   [[layers]]                  # 1 to 8, evaluated in file order
//   name = "continents"         kind = "fbm"              # fbm | ridged | billow
//   octaves = 4                 wavelength_m = 4.0e6      # or frequency_per_m, not both
//   lacunarity = 2.6            gain = 0.5                amplitude_m = 3500.0     offset_m = 0.0
//   modulated_by = "continents" modulation_low_m = 0.0   modulation_high_m = 2000.0
//   modulation_floor = 0.0      # only with modulated_by, which names an earlier layer
//
// Nothing throws out of these functions: every problem (syntax, unknown key, wrong type, NaN/Inf,
// out of range, radius <= 0, too many octaves for double precision) is an Error with the file, the
// 1-based line and column of the offending key or value, and the key's path (e.g. "layers[1].gain").
#include <string>
#include <string_view>

#include "planet/error.h"
#include "planet/planet_description.h"

namespace globe {

// The default planet of every command, relative to the source tree (and the installed data dir).
inline constexpr std::string_view kDefaultPlanetFile = "assets/planets/earthlike.toml";

// Reads and validates a planet file. The description's name defaults to the file's stem.
Result<PlanetDescription> loadPlanetFile(const std::string& path);

// Same, from text already in memory; `source_name` is the file name used in errors.
Result<PlanetDescription> parsePlanetToml(std::string_view text, std::string_view source_name);

}  // namespace globe
