#pragma once
// The quality presets (fast, balanced, exact): the one place that maps a QualityPreset to terrain
// settings. Chosen from the measured speed/accuracy frontier of `globe trade` (docs/tradeoffs.md);
// change them only with a new measurement.
#include "engine/render/terrain.h"
#include "planet/core/error.h"
#include "planet/model/planet_description.h"

#include <string>

namespace globe {

// Terrain settings (grid, LOD ranges) of a preset; streaming, origin and style keep their defaults.
TerrainSettings terrainSettingsFor(QualityPreset preset);

// "fast", "balanced" or "exact"; anything else is an Error naming `field`.
Result<QualityPreset> parseQualityPreset(const std::string& text, const std::string& field);

// The preset a command uses: `option` when given (non-empty), else the planet's default_quality.
Result<QualityPreset> chooseQualityPreset(const std::string& option, const PlanetDescription& planet,
                                          const std::string& field = "--quality");

}  // namespace globe
