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

// The knobs, each set to a value v.
void grid(TerrainSettings& s, double v) { s.gridCells = uint32_t(v); }
void multiplier(TerrainSettings& s, double v) {
  s.ranges.distanceMultiplier = v;
  s.ranges.tolerance_px = 0;  // a multiplier is a distance-range knob
}
// Tolerance-driven ranges (docs/lod.md) instead of distance ranges: the multiplier is unused.
void tolerance(TerrainSettings& s, double v) {
  s.ranges.tolerance_px = v;
  s.ranges.distanceMultiplier = 1;
}
// The same following the relief's roughness (docs/lod.md, "Roughness"): what the roughness buys.
void roughTolerance(TerrainSettings& s, double v) {
  tolerance(s, v);
  s.ranges.roughness = true;
}
void depth(TerrainSettings& s, double v) { s.ranges.maxDepth = int(v); }
// Normal map cells per grid cell (docs/rendering.md, "Surface textures"): shading detail vs generation.
void normalMap(TerrainSettings& s, double v) { s.normalMapScale = uint32_t(v); }
void morph(TerrainSettings& s, double v) { s.ranges.morphFraction = v; }
// Generation in float instead of double (what double buys; never a preset).
void precision(TerrainSettings& s, double v) {
  s.generation = v != 0.0 ? GenerationPrecision::kFloat : GenerationPrecision::kDouble;
}
// The payload's heights re-projected in double every frame instead of its stored positions.
void reproject(TerrainSettings& s, double v) {
  s.vertexPositions = v != 0.0 ? VertexPositions::kReprojected : VertexPositions::kStored;
}

using Knob = void (*)(TerrainSettings&, double);

// The list being built: each set of knobs once, in the order first added.
class Sweep {
 public:
  explicit Sweep(const TerrainSettings& base) : base_(base) {}
  void add(const std::string& label, const TerrainSettings& s) {
    for (const TradeConfig& c : list_)
      if (sameKnobs(c.settings, s)) return;
    list_.push_back({label.empty() ? knobName(s) : label + " (" + knobName(s) + ")", s});
  }
  // The baseline with `knobs` set to `values` (one value each).
  void with(std::initializer_list<std::pair<Knob, double>> knobs) {
    TerrainSettings s = base_;
    for (auto [knob, value] : knobs) knob(s, value);
    add("", s);
  }
  void vary(Knob knob, std::initializer_list<double> values) {
    for (double v : values) with({{knob, v}});
  }
  const TerrainSettings& base() const { return base_; }
  std::vector<TradeConfig> take() { return std::move(list_); }

 private:
  TerrainSettings base_;
  std::vector<TradeConfig> list_;
};

// Distance ranges against tolerance-driven ranges at the baseline's grid and depth.
void lodSweep(Sweep& sweep) {
  if (sweep.base().gridCells >= 32) {  // around exact: sub-pixel errors, where tolerance ranges save most
    sweep.vary(multiplier, {0.5, 0.75, 1, 1.5, 2, 3, 4});
    sweep.vary(tolerance, {0.5, 0.75, 1, 1.5, 2, 3});
    return;
  }
  sweep.vary(multiplier, {0.25, 0.5, 0.75, 1, 1.5, 2, 4});
  sweep.vary(tolerance, {0.5, 1, 2, 3, 4, 6, 8, 16});
  sweep.vary(roughTolerance, {2, 3, 4, 6, 8, 16});
}

// The cheap knobs only: a minute or two on lavapipe.
void quickSweep(Sweep& sweep) {
  sweep.vary(normalMap, {0, 1, 2, 4});
  sweep.vary(grid, {16, 32, 64});
  sweep.vary(multiplier, {0.5, 1, 2});
  sweep.vary(precision, {1});
  sweep.vary(reproject, {1});
  sweep.vary(tolerance, {2});
}

// The presets and the knobs that do not change the triangle count much first (--configs N keeps
// the first N), then grids, multipliers, depths and tolerances in combination.
void fullSweep(Sweep& sweep) {
  for (QualityPreset p : {QualityPreset::kFast, QualityPreset::kBalanced, QualityPreset::kExact})
    sweep.add(std::string(qualityPresetName(p)), terrainSettingsFor(p));
  sweep.vary(normalMap, {0, 1, 2, 4});
  sweep.vary(depth, {16, 20, 24});
  sweep.vary(morph, {0.25, 0.5});
  sweep.vary(precision, {1});
  sweep.vary(reproject, {1});
  sweep.vary(grid, {16, 32, 64, 128});
  sweep.vary(multiplier, {0.5, 1, 2, 4});
  for (auto [g, m] : {std::pair{16.0, 2.0}, {16.0, 4.0}, {64.0, 0.5}, {64.0, 2.0}, {128.0, 0.5}, {128.0, 1.0}})
    sweep.with({{grid, g}, {multiplier, m}});
  // Finer grids with the deepest level: what ground-level cameras need for sub-pixel error.
  for (auto [g, m] : {std::pair{32.0, 1.0}, {32.0, 2.0}, {64.0, 1.0}, {64.0, 2.0}, {128.0, 1.0}})
    sweep.with({{grid, g}, {multiplier, m}, {depth, 24}});
  // The tolerance sweep against the multiplier sweep above (docs/tradeoffs.md, "Tolerance vs distance").
  sweep.vary(tolerance, {0.5, 1, 2, 4, 8, 16});
  for (double t : {1.0, 2.0, 4.0}) sweep.with({{grid, 32}, {tolerance, t}, {depth, 24}});
}

}  // namespace

// One knob at a time around the baseline, then the presets and a few combinations.
std::vector<TradeConfig> tradeConfigs(const TerrainSettings& base, const std::string& baseName, bool quick,
                                      bool lodSweepOnly) {
  Sweep sweep(base);
  sweep.add(baseName, base);
  if (lodSweepOnly)
    lodSweep(sweep);
  else if (quick)
    quickSweep(sweep);
  else
    fullSweep(sweep);
  return sweep.take();
}

}  // namespace globe
