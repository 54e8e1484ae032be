#include "engine/render/quality.h"

namespace globe {

namespace {
// Values from the frontier measured by `globe trade` (docs/tradeoffs.md, "Presets").

// fast: ~75k triangles at the 1 km camera, the cheapest useful view.
TerrainSettings fastSettings() {
  TerrainSettings s;
  s.gridCells = 16;
  // Tolerance-driven ranges: 11 % fewer triangles over the seven trade cameras than the distance
  // multiplier 0.25 it replaces, worst p95 12.0 px instead of 12.5 (docs/tradeoffs.md, "Presets").
  s.ranges.tolerance_px = 32.0;
  // Light per vertex: with surface textures (scale 1) its flyover took 32.6 ms, balanced's cost,
  // against 22.5 ms without; the cheapest preset keeps the cheap path (docs/rendering.md,
  // "Surface textures").
  s.normalMapScale = 0;
  s.detailTextures = DetailTextures::kOff;  // per vertex everywhere: the cheap path
  s.atmosphere = AtmosphereDetail::kSky;
  return s;
}

// balanced: ~48k triangles at 1 km; the flyover's median ~31 ms at 1280x720 on lavapipe (goal 33).
TerrainSettings balancedSettings() {
  TerrainSettings s;
  // 8 cells a node, 32 texels (scale 4): the detail is per pixel, so the vertices are for
  // silhouettes and parallax only. A quarter of grid 16's triangles for the same nodes: on lavapipe
  // the flyover's median 42.4 -> 30.8 ms, along the ground 64 -> 51 ms (docs/rendering.md,
  // "Eight cells a node"). Tolerance-driven ranges (docs/lod.md) at 8 px keep grid 16's screen
  // error at 16 px (p95 5.1 px at 1 km, 3.5 px at 2 m); at 16 px grid 8 lost SSIM at 2 m (0.79 ->
  // 0.76). The price: rough relief right under the camera takes one level more (the 2 m camera
  // 110 ms instead of 75).
  s.gridCells = 8;
  s.ranges.tolerance_px = 8.0;
  // The texel rule at 16 px (--texel-px): plains seen from 100 km no longer draw 32-texel
  // surfaces magnified to 30+ px (SSIM against exact's structure 0.76 -> 0.89 there, 0.87 ->
  // 0.88 at 10 km) for ~1 ms of the flyover's median (32.7 -> 33.5-34.0 ms); 8 px took it to
  // 35 ms, 4 px to 39 ms (docs/lod.md, "Texel rule"; docs/rendering.md, "Colour").
  s.ranges.texel_px = 16.0;
  // Depth 24 instead of 20: the same nodes above ~100 m, and at the 2 m camera p95 6.1 px
  // instead of 10.5 px for the same frame time (globe trade, 2026-11-22).
  s.ranges.maxDepth = 24;
  // Per-pixel light, colour and coast from the payloads' surface textures, 32 texels a node side
  // (at grid 16, scale 4's 64 texels spent 3.6 ms a frame generating them: docs/rendering.md,
  // "Surface textures"; at grid 8, scale 8's 64 texels double the fine detail at 1 km for +6 ms
  // along the ground: "Sixty-four texels a node").
  s.normalMapScale = 4;
  // The land cover's detail textures near the ground only (below ~100 m they are what the surface
  // shows; everywhere they took the flight's median from 21 to 33 ms on lavapipe): farther away
  // the classes' colours per vertex (docs/rendering.md, "Land cover", "Ground detail").
  s.detailTextures = DetailTextures::kNear;
  // The sky, the ground lit and seen through the air by the analytic haze's per-frame constants:
  // `full`'s per-vertex tables cost +20-30 % of the flyover's frame on lavapipe, over the goal
  // (docs/rendering.md, "Atmosphere", "Haze").
  s.atmosphere = AtmosphereDetail::kSky;
  return s;
}

// exact: p95 screen error <= 0.5 px at 1280x720 at every standard camera.
TerrainSettings exactSettings() {
  TerrainSettings s;
  s.gridCells = 64;
  s.ranges.distanceMultiplier = 2.0;
  // FXAA's fixed ~16 ms of CPU a 1280x720 frame is ~1 % of this preset's frame; on fast and
  // balanced it is +40 % (MSAA x4 +160 %) of the flyover's CPU: docs/rendering.md, "Anti-aliasing".
  s.antialiasing = Antialiasing::kFxaa;
  s.normalMapScale = 1;  // 64 map cells a node; scale 2 would fit only 1549 slots in 512 MiB
  // The maps from imagery tiles of their own LOD: each texel <= 1.5 px at 1280x720 from 100 km to
  // 1 km where the mesh's own maps reach 2.9 px, and 2.8 px instead of 45 px at 2 m
  // (docs/rendering.md, "Imagery LOD"); --imagery off falls back to the mesh's maps above.
  s.imagery = true;
  // The complete atmosphere (light and aerial perspective per vertex): 2.4x the frame at 1 km,
  // 1.65x at 2 m (docs/rendering.md, "Atmosphere"); the reference-quality preset keeps it.
  s.atmosphere = AtmosphereDetail::kFull;
  // Cast shadows of the relief (docs/rendering.md, "Shadows").
  s.shadows = true;
  return s;
}

}  // namespace

TerrainSettings terrainSettingsFor(QualityPreset preset) {
  switch (preset) {
    case QualityPreset::kFast:
      return fastSettings();
    case QualityPreset::kBalanced:
      return balancedSettings();
    case QualityPreset::kExact:
      return exactSettings();
  }
  return balancedSettings();
}

Result<QualityPreset> parseQualityPreset(const std::string& text, const std::string& field) {
  if (auto preset = qualityPresetFromName(text)) return *preset;
  return Error::inField(field, "unknown quality '" + text + "' (fast, balanced, exact)");
}

Result<QualityPreset> chooseQualityPreset(const std::string& option, const PlanetDescription& planet,
                                          const std::string& field) {
  if (option.empty()) return planet.default_quality;
  return parseQualityPreset(option, field);
}

}  // namespace globe
