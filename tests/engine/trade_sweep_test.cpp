// The configurations `globe trade` sweeps (engine/measure/trade_sweep.h): the baseline first, each
// set of knobs once, the presets in the full sweep, one LOD rule's knobs in the LOD sweep.
#include "engine/measure/trade_sweep.h"
#include "engine/render/quality.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace globe {
namespace {

void expectEachOnce(const std::vector<TradeConfig>& configs) {
  std::set<std::string> names;
  for (const TradeConfig& c : configs) EXPECT_TRUE(names.insert(c.name).second) << c.name;
}

TEST(TradeSweep, BaselineFirstAndEachConfigurationOnce) {
  const TerrainSettings balanced = terrainSettingsFor(QualityPreset::kBalanced);
  for (bool quick : {false, true}) {
    for (bool lod : {false, true}) {
      const std::vector<TradeConfig> configs = tradeConfigs(balanced, "balanced", quick, lod);
      ASSERT_FALSE(configs.empty());
      EXPECT_EQ(configs.front().name.rfind("balanced (", 0), 0u) << configs.front().name;
      expectEachOnce(configs);
    }
  }
}

TEST(TradeSweep, TheFullSweepHoldsThePresets) {
  const std::vector<TradeConfig> configs =
      tradeConfigs(terrainSettingsFor(QualityPreset::kBalanced), "balanced", false, false);
  for (const char* preset : {"fast (", "exact ("}) {
    EXPECT_TRUE(std::any_of(configs.begin(), configs.end(), [&](const TradeConfig& c) {
      return c.name.rfind(preset, 0) == 0;
    })) << preset;
  }
}

TEST(TradeSweep, TheLodSweepVariesOnlyTheLodRule) {
  const TerrainSettings exact = terrainSettingsFor(QualityPreset::kExact);
  const std::vector<TradeConfig> configs = tradeConfigs(exact, "exact", false, true);
  EXPECT_GT(configs.size(), 8u);
  for (const TradeConfig& c : configs) {
    EXPECT_EQ(c.settings.gridCells, exact.gridCells) << c.name;
    EXPECT_EQ(c.settings.ranges.maxDepth, exact.ranges.maxDepth) << c.name;
  }
}

}  // namespace
}  // namespace globe
