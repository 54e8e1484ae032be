#pragma once
// Writes a PlanetDescription back as a TOML planet file that loadPlanetFile reads to an equal
// description (every number printed in its shortest round-trip form). Used by the preset round-trip
// tests and by tools that generate planets.
#include <string>

#include "planet/model/planet_description.h"

namespace globe {

// `planet` must be valid (validatePlanet). Every key is written, defaults included.
std::string formatPlanetToml(const PlanetDescription& planet);

}  // namespace globe
