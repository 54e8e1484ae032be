#pragma once
// The configurations `globe trade` sweeps (docs/tradeoffs.md): one knob at a time around a baseline,
// the presets and a few combinations; or only the LOD rules (distance multipliers against
// tolerances); or, quick, the cheap knobs only.
#include "engine/render/terrain.h"

#include <string>
#include <vector>

namespace globe {

struct TradeConfig {
  std::string name;  // the label (a preset's name) and the knobs, e.g. "balanced (g16 x1 d24 f0.5 n1)"
  TerrainSettings settings;
};

// `base`: the baseline's settings, named `baseName`. Configurations with the same knobs appear once.
std::vector<TradeConfig> tradeConfigs(const TerrainSettings& base, const std::string& baseName, bool quick,
                                      bool lodSweepOnly);

}  // namespace globe
