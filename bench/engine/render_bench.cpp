// Frame time of the terrain at the five standard cameras (orbit, 100 km, 10 km, 1 km, 2 m), 1280x720,
// converged (every payload resident: render cost alone), with triangles and draw calls per frame.
//
//   build/release/bin/engine_bench --benchmark_filter=TerrainFrame
// Knobs: GLOBE_BENCH_QUALITY (fast|balanced|exact, default balanced), then overrides
// GLOBE_BENCH_GRID (cells per node side) and GLOBE_BENCH_RANGE (LOD distance multiplier);
// GLOBE_BENCH_LAND_COVER=off drops the planet's land cover (the colour ramp instead);
// GLOBE_BENCH_DETAIL=on|near|off overrides the preset's detail textures (TerrainSettings::detailTextures).
#include "bench_support.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/quality.h"
#include "planet/model/planet_file.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace globe {
namespace {

using bench::device;
const PlanetDescription& planet() {
  static const PlanetDescription p = [] {
    PlanetDescription d = bench::earthlike();
    if (const char* cover = std::getenv("GLOBE_BENCH_LAND_COVER"); cover && std::string(cover) == "off")
      d.land_cover = {};
    return d;
  }();
  return p;
}

void BM_TerrainFrame(benchmark::State& state) {
  const int index = int(state.range(0));
  static const ElevationModel model(planet());
  QualityPreset quality = QualityPreset::kBalanced;
  if (const char* q = std::getenv("GLOBE_BENCH_QUALITY")) {
    auto parsed = parseQualityPreset(q, "GLOBE_BENCH_QUALITY");
    if (!parsed) {
      state.SkipWithError(parsed.error().format().c_str());
      return;
    }
    quality = *parsed;
  }
  TerrainSettings settings = terrainSettingsFor(quality);
  if (const char* g = std::getenv("GLOBE_BENCH_GRID")) settings.gridCells = uint32_t(std::atoi(g));
  if (const char* r = std::getenv("GLOBE_BENCH_RANGE")) settings.ranges.distanceMultiplier = std::atof(r);
  if (const char* d = std::getenv("GLOBE_BENCH_DETAIL")) {
    auto detail = parseDetailTextures(d, "GLOBE_BENCH_DETAIL");
    if (!detail) {
      state.SkipWithError(detail.error().format().c_str());
      return;
    }
    settings.detailTextures = *detail;
  }
  GeodeticPose pose = standardCameraPose(index);
  glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
  Camera camera = cameraFromPose(pose, model.radius_m() + model.elevation_m(down), model.shape(), 1280.0 / 720.0);
  settings.style.sunDirection = defaultSunDirection(camera.position_m);
  auto terrain = Terrain::create(device(), model, settings);
  if (!terrain) {
    state.SkipWithError(terrain.error().format().c_str());
    return;
  }
  HeadlessRenderer renderer(device(), {1280, 720});
  FrameStats stats = renderer.renderFrame(**terrain, camera, true);  // converge + warm-up
  double gpu = 0;
  for (auto _ : state) {
    stats = renderer.renderFrame(**terrain, camera, true);
    state.SetIterationTime(stats.frame_ms * 1e-3);
    gpu += stats.gpu_ms;
  }
  state.counters["gpu_ms"] = gpu / double(state.iterations());
  state.counters["select_ms"] = stats.select_ms;
  state.counters["nodes"] = stats.nodes_selected;
  state.counters["triangles"] = double(stats.triangles);
  state.counters["draw_calls"] = stats.draw_calls;
  state.counters["resident_MiB"] = stats.resident_mib;
  state.counters["grid"] = settings.gridCells;
}
BENCHMARK(BM_TerrainFrame)
    ->ArgName("camera")  // 0 orbit, 1 100 km, 2 10 km, 3 1 km, 4 2 m
    ->DenseRange(0, 4)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

}  // namespace
}  // namespace globe
