#include "engine/measure/trade_sweep.h"

#include "engine/render/quality.h"

#include <cstdio>

namespace globe {

namespace {

std::string knobName(const TerrainSettings& s) {
  char lod[32];  // tolerance ranges ignore the multiplier: name the tolerance instead
  if (s.ranges.tolerance_px > 0)
    std::snprintf(lod, sizeof(lod), "t%gpx%s", s.ranges.tolerance_px, s.ranges.roughness ? " roughness" : "");
  else
    std::snprintf(lod, sizeof(lod), "x%g", s.ranges.distanceMultiplier);
  char text[128];
  std::snprintf(text, sizeof(text), "g%u %s d%d f%g n%u%s%s", s.gridCells, lod, s.ranges.maxDepth,
                s.ranges.morphFraction, s.normalMapScale, s.generation == GenerationPrecision::kFloat ? " float" : "",
                s.vertexPositions == VertexPositions::kReprojected ? " reprojected" : "");
  return text;
}

bool sameKnobs(const TerrainSettings& a, const TerrainSettings& b) {
  return a.gridCells == b.gridCells && a.ranges.distanceMultiplier == b.ranges.distanceMultiplier &&
         a.ranges.maxDepth == b.ranges.maxDepth && a.ranges.morphFraction == b.ranges.morphFraction &&
         a.generation == b.generation && a.vertexPositions == b.vertexPositions &&
         a.ranges.tolerance_px == b.ranges.tolerance_px && a.ranges.roughness == b.ranges.roughness &&
         a.normalMapScale == b.normalMapScale && a.detailTextures == b.detailTextures;
}

}  // namespace

// One knob at a time around the baseline, then the presets and a few combinations.
std::vector<TradeConfig> tradeConfigs(const TerrainSettings& base, const std::string& baseName, bool quick,
                                      bool lodSweep) {
  std::vector<TradeConfig> list;
  auto add = [&](const std::string& label, TerrainSettings s) {
    for (const TradeConfig& c : list)
      if (sameKnobs(c.settings, s)) return;
    list.push_back({label.empty() ? knobName(s) : label + " (" + knobName(s) + ")", s});
  };
  add(baseName, base);
  auto vary = [&](auto set, std::initializer_list<double> values) {
    for (double v : values) {
      TerrainSettings s = base;
      set(s, v);
      add("", s);
    }
  };
  auto grid = [](TerrainSettings& s, double v) { s.gridCells = uint32_t(v); };
  auto mult = [](TerrainSettings& s, double v) {
    s.ranges.distanceMultiplier = v;
    s.ranges.tolerance_px = 0;  // a multiplier is a distance-range knob
  };
  // Tolerance-driven ranges (docs/lod.md) instead of distance ranges: the multiplier is unused.
  auto tolerance = [](TerrainSettings& s, double v) {
    s.ranges.tolerance_px = v;
    s.ranges.distanceMultiplier = 1;
  };
  // The same following the relief's roughness (docs/lod.md, "Roughness"): what the roughness buys.
  auto roughTolerance = [&](TerrainSettings& s, double v) {
    tolerance(s, v);
    s.ranges.roughness = true;
  };
  auto depth = [](TerrainSettings& s, double v) { s.ranges.maxDepth = int(v); };
  // Normal map cells per grid cell (docs/rendering.md, "Surface textures"): shading detail vs generation.
  auto normalMap = [](TerrainSettings& s, double v) { s.normalMapScale = uint32_t(v); };
  auto morph = [](TerrainSettings& s, double v) { s.ranges.morphFraction = v; };
  // Generation in float instead of double (what double buys; never a preset).
  auto precision = [](TerrainSettings& s, double v) {
    s.generation = v != 0.0 ? GenerationPrecision::kFloat : GenerationPrecision::kDouble;
  };
  // The payload's heights re-projected in double every frame instead of its stored positions.
  auto reproject = [](TerrainSettings& s, double v) {
    s.vertexPositions = v != 0.0 ? VertexPositions::kReprojected : VertexPositions::kStored;
  };
  if (lodSweep && base.gridCells >= 32) {  // around exact: sub-pixel errors, where tolerance ranges save most
    vary(mult, {0.5, 0.75, 1, 1.5, 2, 3, 4});
    vary(tolerance, {0.5, 0.75, 1, 1.5, 2, 3});
    return list;
  }
  if (lodSweep) {  // distance ranges vs tolerance-driven ranges at the baseline's grid and depth
    vary(mult, {0.25, 0.5, 0.75, 1, 1.5, 2, 4});
    vary(tolerance, {0.5, 1, 2, 3, 4, 6, 8, 16});
    vary(roughTolerance, {2, 3, 4, 6, 8, 16});
    return list;
  }
  if (quick) {  // the cheap knobs only: a minute or two on lavapipe
    vary(normalMap, {0, 1, 2, 4});
    vary(grid, {16, 32, 64});
    vary(mult, {0.5, 1, 2});
    vary(precision, {1});
    vary(reproject, {1});
    vary(tolerance, {2});
    return list;
  }
  // The presets and the knobs that do not change the triangle count much first: --configs N keeps
  // the first N.
  for (QualityPreset p : {QualityPreset::kFast, QualityPreset::kBalanced, QualityPreset::kExact})
    add(std::string(qualityPresetName(p)), terrainSettingsFor(p));
  vary(normalMap, {0, 1, 2, 4});
  vary(depth, {16, 20, 24});
  vary(morph, {0.25, 0.5});
  vary(precision, {1});
  vary(reproject, {1});
  vary(grid, {16, 32, 64, 128});
  vary(mult, {0.5, 1, 2, 4});
  for (auto [g, m] : {std::pair{16.0, 2.0}, {16.0, 4.0}, {64.0, 0.5}, {64.0, 2.0}, {128.0, 0.5}, {128.0, 1.0}}) {
    TerrainSettings s = base;
    grid(s, g);
    mult(s, m);
    add("", s);
  }
  // Finer grids with the deepest level: what ground-level cameras need for sub-pixel error.
  for (auto [g, m] : {std::pair{32.0, 1.0}, {32.0, 2.0}, {64.0, 1.0}, {64.0, 2.0}, {128.0, 1.0}}) {
    TerrainSettings s = base;
    grid(s, g);
    mult(s, m);
    depth(s, 24);
    add("", s);
  }
  // The tolerance sweep against the multiplier sweep above (docs/tradeoffs.md, "Tolerance vs distance").
  vary(tolerance, {0.5, 1, 2, 4, 8, 16});
  for (double t : {1.0, 2.0, 4.0}) {
    TerrainSettings s = base;
    grid(s, 32);
    tolerance(s, t);
    depth(s, 24);
    add("", s);
  }
  return list;
}

}  // namespace globe
