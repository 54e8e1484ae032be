#pragma once
// What `globe planet check` reports about a valid planet's sources: per source its size, CRS,
// pixel size, latitude/longitude box, value range and valid-pixel coverage, then every pair whose
// boxes overlap (and which one wins there: the finer, then the higher priority).
#include "planet/elevation/planet_description.h"

#include <string>
#include <vector>

namespace globe {

std::vector<std::string> describeSources(const PlanetDescription& planet);

}  // namespace globe
