#pragma once
// Reading a planet file's [atmosphere] table (planet/model/planet_file.cpp calls it), key by key
// like every other table: each problem is one Error at the key's line and column. Keys not given
// keep Earth's values (AtmosphereParameters' defaults); ranges are checked by validateAtmosphere.
#include "planet/atmosphere/atmosphere_parameters.h"
#include "planet/core/planet_toml_reader.h"

namespace globe {

void readAtmosphere(PlanetTomlReader& r, const toml::node& node, AtmosphereParameters& atmosphere);

// The [atmosphere] table as a planet file writes it (every key, defaults included).
std::string formatAtmosphereToml(const AtmosphereParameters& atmosphere);

}  // namespace globe
