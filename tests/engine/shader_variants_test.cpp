// No shader compile per frame (docs/rendering.md): lavapipe (Mesa 22.3) re-compiles a pipeline's shader at
// draw time whenever it decides to inline push-constant or uniform-buffer values into it, and with
// no variant cache it does so at every bind (100-200 ms each, docs/rendering.md "No shader compile
// per frame"). Every variant it compiles is a new entry in Mesa's on-disk shader cache, so the
// guard counts the entries of a cache pointed at an empty directory: after a few warm-up frames,
// 21 frames at 21 different cameras (moving floating origin, altitudes from 2 m to 2e7 m and 1e11 m so the
// morph ranges change, sun directions, debug views, generation batches of different sizes) plus
// elevation batches and sphere previews with the latitude/longitude grid, of different sizes, must
// add none; the same views over a DEM with a kept no-data hole (a `nodata = "hole"` source: the
// double-sided terrain_holes.frag pipeline) too. The earthlike planet has an atmosphere, so its
// pipelines are the ones with aerial perspective and the atmosphere's sky, from 2 m to 1e11 m. No
// timing is asserted.
#include "engine/generation/elevation_sampler.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/offscreen_target.h"
#include "engine/render/sphere_grid.h"
#include "engine/render/sphere_preview.h"
#include "planet/model/planet_file.h"
#include "tests/support/dem_fixture.h"
#include "tests/support/gpu_test.h"
#include "tests/support/temp_dir.h"

#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace globe::testing {
namespace {

namespace fs = std::filesystem;

// Entries of Mesa's multi-file cache (mesa_shader_cache/xx/yyyy...), without its size index.
size_t cacheEntries(const fs::path& dir) {
  size_t n = 0;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_regular_file() && it->path().filename() != "index") ++n;
  }
  return n;
}

// Mesa writes cache entries from a worker thread; destroying the instance (the Device) finishes
// them, and polling until two reads 200 ms apart agree covers any write still landing.
size_t settledCacheEntries(const fs::path& dir) {
  size_t last = cacheEntries(dir);
  for (int i = 0; i < 50; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const size_t now = cacheEntries(dir);
    if (now == last) return now;
    last = now;
  }
  return last;
}

struct View {
  GeodeticPose pose;
  glm::dvec3 sun;
  TerrainDebugView debug = TerrainDebugView::kShaded;
};

// The warm-up views: each kind of frame once (shaded, LOD colours, sphere preview, elevation batch).
std::vector<View> warmUpViews() {
  return {{{22.05, -98.4, 1000.0, 60, -10, 0}, {1.0, 0.4, 0.6}},
          {{22.05, -98.4, 1000.0, 60, -10, 0}, {1.0, 0.4, 0.6}, TerrainDebugView::kLodColours},
          {{22.0, -99.0, 1.0e5, 60, -30, 0}, {0.3, 1.0, 0.2}}};
}

// 20 cameras: a descent from orbit to 2 m over changing places, sun and debug view.
std::vector<View> variedViews() {
  std::vector<View> views;
  for (int i = 0; i < 20; ++i) {
    const double height_m = 2.0e7 * std::pow(1.0e-7, i / 19.0);  // 2e7 m ... 2 m
    const double a = 0.3 * i;
    View v{{22.0 + 0.01 * i, -98.5 + 0.013 * i, height_m, 40.0 + 7.0 * i, -5.0 - 2.0 * (i % 7), 0},
           {std::cos(a), std::sin(a), 0.5 + 0.02 * i}};
    if (i % 5 == 3) v.debug = TerrainDebugView::kLodColours;
    views.push_back(v);
  }
  // The atmosphere's other regime: a camera far outside it (the sky shader's entry point, the
  // terrain's aerial perspective from space), the sun moved again.
  views.push_back({{22.0, -98.5, 1.0e11, 0, -90, 0}, {0.2, -0.9, 0.4}});
  return views;
}

// The view moved by the same offsets to the Jacksboro DEM's no-data blob (tests/support/dem_fixture.h).
GeodeticPose overTheHole(GeodeticPose pose) {
  pose.latitude_deg += 36.59 - 22.0;
  pose.longitude_deg += -84.25 + 98.5;
  return pose;
}

// One process-like run on a fresh device (its own Mesa screen and cache handle): the views through
// Terrain + HeadlessRenderer (budgeted frames, every fourth converged, so generation batches vary
// in size; the planet with MSAA x4, the DEM with FXAA), each view also as a sphere preview and an
// elevation batch of a different size.
void renderViews(const std::vector<View>& views, const ElevationModel& holes) {
  vk::DeviceOptions options;
  options.validation = true;
  options.deviceName = vk::deviceNameFromEnvironment();
  vk::Device device(options);
  const ElevationModel& model = earthlikeModel();
  TerrainSettings settings;
  settings.gridCells = 16;
  settings.antialiasing = Antialiasing::kMsaa4;
  auto terrain = Terrain::create(device, model, settings);
  ASSERT_TRUE(terrain.ok()) << terrain.error().format();
  // The earthlike planet has an [atmosphere]: its sky and terrain pipelines are the ones guarded.
  ASSERT_NE((*terrain)->atmosphere(), nullptr);
  const uint32_t w = 96, h = 64;
  HeadlessRenderer renderer(device, {w, h}), holeRenderer(device, {w, h});
  OffscreenTarget sphereTarget(device, {w, h});
  SpherePreview sphere(device);
  SphereGrid grid(device);
  ElevationSampler sampler(device, model.params(), 512);
  settings.antialiasing = Antialiasing::kFxaa;
  auto holeTerrain = Terrain::create(device, holes, settings);
  ASSERT_TRUE(holeTerrain.ok()) << holeTerrain.error().format();
  ASSERT_TRUE((*holeTerrain)->renderer().style().holes);
  int k = 0;
  for (const View& v : views) {
    const glm::dvec3 down = directionFromLatLon(v.pose.latitude_deg, v.pose.longitude_deg);
    const Camera camera = cameraFromPose(v.pose, (*terrain)->cameraGroundRadius(down), model.radius_m(), double(w) / h);
    TerrainStyle style = (*terrain)->renderer().style();
    style.sunDirection = v.sun;
    style.debug = v.debug;
    (*terrain)->renderer().setStyle(style);
    renderer.renderFrame(**terrain, camera, k % 4 == 0);
    const float clear[4] = {0, 0, 0, 1};
    device.submitAndWait([&](VkCommandBuffer cmd) {
      sphereTarget.begin(cmd, clear);
      sphere.record(cmd, camera, model.radius_m() * (1.0 + 1e-3 * k), v.sun);
      grid.record(cmd, camera, model.radius_m(), 5.0 + k);
      sphereTarget.end(cmd);
    });
    sampler.sample(std::vector<glm::dvec3>(size_t(1 + 13 * k), glm::normalize(camera.position_m)));
    const GeodeticPose pose = overTheHole(v.pose);
    const glm::dvec3 holeDown = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
    const Camera holeCamera =
        cameraFromPose(pose, (*holeTerrain)->cameraGroundRadius(holeDown), holes.radius_m(), double(w) / h);
    TerrainStyle holeStyle = (*holeTerrain)->renderer().style();  // keeps `holes`
    holeStyle.sunDirection = v.sun;
    holeStyle.debug = v.debug;
    (*holeTerrain)->renderer().setStyle(holeStyle);
    holeRenderer.renderFrame(**holeTerrain, holeCamera, k % 4 == 0);
    ++k;
  }
  const auto messages = device.validation().messages();
  EXPECT_TRUE(messages.empty()) << messages.size()
                                << " validation message(s), first: " << (messages.empty() ? "" : messages.front());
}

TEST(ShaderVariants, NoNewShaderVariantsAfterWarmUp) {
  const fs::path cache = fs::temp_directory_path() / ("globe-shader-cache-" + std::to_string(::getpid()));
  fs::remove_all(cache);
  fs::create_directories(cache);
  ::setenv("MESA_SHADER_CACHE_DIR", cache.c_str(), 1);
  ::unsetenv("MESA_SHADER_CACHE_DISABLE");
  ::unsetenv("MESA_GLSL_CACHE_DISABLE");

  const TempDir dir("shader_variants");
  ::setenv("GLOBE_SOURCE_CACHE_DIR", (dir.str() / fs::path("sources")).c_str(), 1);
  const DemFixture dem(dir.str() / fs::path(), std::string(GLOBE_SOURCE_DIR) + "/assets/planets/dem/jacksboro.vrt");
  Result<PlanetDescription> planet = loadPlanetFile(
      writeDemPlanet(dir.str(), "holes", "[[sources]]\npath = \"" + dem.holes + "\"\nnodata = \"hole\"\n"));
  ASSERT_TRUE(planet.ok()) << planet.error().format();
  const ElevationModel holes(*planet);

  renderViews(warmUpViews(), holes);
  const size_t afterWarmUp = settledCacheEntries(cache);
  std::vector<View> views = warmUpViews();
  for (const View& v : variedViews()) views.push_back(v);
  renderViews(views, holes);
  ::unsetenv("GLOBE_SOURCE_CACHE_DIR");
  const size_t afterVaried = settledCacheEntries(cache);
  std::printf("[ info ] shader cache entries: %zu after warm-up, %zu after 21 more cameras\n", afterWarmUp,
              afterVaried);
  fs::remove_all(cache);
  if (afterWarmUp == 0) GTEST_SKIP() << "the Vulkan driver keeps no Mesa shader cache (not lavapipe?)";
  EXPECT_EQ(afterVaried, afterWarmUp) << "a pipeline was compiled again for new push-constant/uniform values "
                                         "(lavapipe inlines them; docs/rendering.md, \"No shader compile per frame\")";
}

}  // namespace
}  // namespace globe::testing
