// The atmosphere on screen (docs/rendering.md, "Atmosphere"): the earthlike planet (its [atmosphere])
// rendered at 1 cm, 2 m, 1 km, 100 km, 2e7 m and 1e11 m and at sunset. Everywhere the sky should be
// lit it is (a NaN stores as 0, so this also finds NaNs): every background pixel from inside the
// atmosphere, every background pixel whose ray grazes the air below 20 km from outside it (the limb
// glow). The airless moonlike planet's background is black. From 2 m the sky at the horizon is blue
// (B > R) with the sun 45 degrees up and red towards a sun 2 degrees up (R > B); distant terrain
// (40-60 km) has less contrast than near terrain (1-3 km): aerial perspective.
#include "engine/render/headless_renderer.h"
#include "engine/render/render_output.h"
#include "engine/vk/compute_pipeline.h"
#include "planet/paths/camera_path_file.h"
#include "tests/support/gpu_test.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace globe::testing {
namespace {

constexpr uint32_t kWidth = 240, kHeight = 135;

struct Frame {
  Camera camera;
  ImageRgba image;
  glm::dvec3 sun{0.0};
};

class AtmosphereRenderTest : public GpuTest {
 protected:
  // A converged frame over the earthlike plateau at `pose`, the sun at `sun` in its sky; `inspect`
  // sees the terrain and the frame before the terrain goes.
  Frame render(const ElevationModel& model, GeodeticPose pose, SunAngles sun,
               const std::function<void(Terrain&, const Frame&)>& inspect = {},
               AtmosphereDetail detail = AtmosphereDetail::kFull) {
    const glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
    auto terrain = makeTerrain(model, detail);
    const Camera camera =
        cameraFromPose(pose, terrain->cameraGroundRadius(down), model.shape(), double(kWidth) / kHeight);
    return draw(*terrain, camera, sunDirectionAt(camera.position_m, sun), inspect);
  }

  std::unique_ptr<Terrain> makeTerrain(const ElevationModel& model, AtmosphereDetail detail = AtmosphereDetail::kFull) {
    TerrainSettings settings;
    settings.gridCells = 16;
    settings.atmosphere = detail;
    auto terrain = Terrain::create(device(), model, settings);
    EXPECT_TRUE(terrain.ok());
    return std::move(*terrain);
  }

  // A converged frame of `terrain` from `camera`, lit from the unit direction `sun`.
  Frame draw(Terrain& terrain, const Camera& camera, const glm::dvec3& sun,
             const std::function<void(Terrain&, const Frame&)>& inspect = {}) {
    TerrainStyle style = terrain.renderer().style();
    style.sunDirection = sun;
    terrain.renderer().setStyle(style);
    HeadlessRenderer renderer(device(), {kWidth, kHeight});
    renderer.renderFrame(terrain, camera, true);
    Frame frame{camera, toImage(renderer.readback(), camera), sun};
    if (inspect) inspect(terrain, frame);
    return frame;
  }
};

glm::dvec3 pixelRay(const Camera& c, uint32_t x, uint32_t y) {
  const double tanY = std::tan(c.verticalFov_rad * 0.5);
  const double nx = (x + 0.5) / kWidth * 2.0 - 1.0, ny = (y + 0.5) / kHeight * 2.0 - 1.0;
  return glm::normalize(c.forward + nx * tanY * c.aspect * c.right - ny * tanY * c.up);
}

struct SkyCount {
  int expectedLit = 0;  // background pixels whose ray goes through dense air
  int dark = 0;         // ... of which are black
  int lit = 0;          // background pixels not black
};

// Background pixels (nothing drawn) that must be lit: all of them inside the atmosphere; from outside
// it, those whose ray passes within 20 km of the ground (and not through the planet) where the sun
// stands over 20 degrees above the horizon.
SkyCount countSky(const Frame& f, double bottom_m, double top_m, const glm::dvec3& sun) {
  SkyCount count;
  const glm::dvec3 c = f.camera.position_m;
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      const size_t i = size_t(y) * kWidth + x;
      if (std::isfinite(f.image.z[i])) continue;  // terrain
      const float* p = &f.image.rgba[4 * i];
      const bool black = p[0] < 1.5f / 255 && p[1] < 1.5f / 255 && p[2] < 1.5f / 255;
      count.lit += black ? 0 : 1;
      const glm::dvec3 v = pixelRay(f.camera, x, y);
      const double impact = glm::length(glm::cross(c, v));
      const bool inside = glm::length(c) < top_m;
      const glm::dvec3 closest = c - glm::dot(c, v) * v;
      const bool grazes = glm::dot(c, v) < 0.0 && impact > bottom_m + 1000.0 && impact < bottom_m + 20000.0 &&
                          glm::dot(glm::normalize(closest), sun) > 0.35;
      if (inside || grazes) {
        ++count.expectedLit;
        count.dark += black ? 1 : 0;
      }
    }
  }
  return count;
}

// A named camera pose and the sun in its sky.
struct View {
  const char* name;
  GeodeticPose pose;
  SunAngles sun;
};

TEST_F(AtmosphereRenderTest, SkyIsLitWhereverItShouldBeFromOneCentimetreToOneHundredMillionKilometres) {
  const ElevationModel& model = earthlikeModel();
  ASSERT_TRUE(model.atmosphere().has_value());
  const double bottom = model.radius_m(), top = bottom + model.atmosphere()->thickness_m;
  const View views[] = {
      {"1 cm", {22.0, -98.4, 0.01, 90.0, 10.0, 0.0}, {90.0, 30.0}},
      {"2 m", {22.0, -98.4, 2.0, 90.0, 5.0, 0.0}, {90.0, 30.0}},
      {"1 km", {22.0, -98.4, 1000.0, 90.0, 0.0, 0.0}, {270.0, 30.0}},
      {"100 km", {22.0, -98.4, 1.0e5, 90.0, -5.0, 0.0}, {90.0, 30.0}},
      {"2e7 m", {22.0, -98.4, 2.0e7, 0.0, -90.0, 0.0}, {90.0, 30.0}},
      {"1e11 m", {22.0, -98.4, 1.0e11, 0.0, -90.0, 0.0}, {90.0, 30.0}},
      {"sunset, 2 m", {22.0, -98.4, 2.0, 90.0, 3.0, 0.0}, {90.0, 1.0}},
  };
  for (const View& view : views) {
    const Frame f = render(model, view.pose, view.sun);
    const SkyCount sky = countSky(f, bottom, top, f.sun);
    std::printf("[ info ] %s: %d sky pixels that must be lit, %d black; %d lit in all\n", view.name, sky.expectedLit,
                sky.dark, sky.lit);
    EXPECT_EQ(sky.dark, 0) << view.name;
    if (view.pose.height_m == 2.0e7) {
      EXPECT_GT(sky.expectedLit, 0) << "the lit limb is in view";
      EXPECT_GT(sky.lit, 20) << "the limb glows outside the solid disc";
    }
  }
}

// The standard flight's first key frame (globe bench, assets/paths/flyover.path at t = 0: 800 km up,
// looking 45 degrees down), lit as the bench lights it: the limb glows above the planet's edge.
TEST_F(AtmosphereRenderTest, FlyoverFirstKeyFrameShowsTheLimbGlow) {
  const ElevationModel& model = earthlikeModel();
  auto path = loadCameraPath(std::string(GLOBE_SOURCE_DIR) + "/assets/paths/flyover.path");
  ASSERT_TRUE(path.ok()) << path.error().format();
  auto terrain = makeTerrain(model);
  const GroundRadiusFn ground = [&](const glm::dvec3& d) { return terrain->cameraGroundRadius(d); };
  const double t = path->startTime_s();
  const Camera camera = path->cameraAt(t, model.radius_m(), double(kWidth) / kHeight, ground, model.shape());
  const glm::dvec3 start =
      path->positionAt(t, [&](const glm::dvec3& d) { return model.radius_m() + model.visibleElevation_m(d); });
  const std::optional<SunAngles>& pathSun = path->keyframes().front().sun;
  const Frame f = draw(*terrain, camera, pathSun ? sunDirectionAt(start, *pathSun) : defaultSunDirection(start));
  const double bottom = model.radius_m(), top = bottom + model.atmosphere()->thickness_m;
  const SkyCount sky = countSky(f, bottom, top, f.sun);
  std::printf("[ info ] flyover t = 0: %d grazing sky pixels, %d black; %d lit\n", sky.expectedLit, sky.dark, sky.lit);
  EXPECT_GT(sky.expectedLit, 20);
  EXPECT_EQ(sky.dark, 0);
  EXPECT_GT(sky.lit, 20);
}

TEST_F(AtmosphereRenderTest, AirlessPlanetHasABlackSky) {
  auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/moonlike.toml");
  ASSERT_TRUE(planet.ok());
  ASSERT_FALSE(planet->atmosphere.has_value());
  const ElevationModel model(*planet);
  for (double height : {2.0, 2.0e7}) {
    const Frame f = render(model, {10.0, 20.0, height, 0.0, height > 1e6 ? -90.0 : 5.0, 0.0}, {90.0, 30.0});
    EXPECT_EQ(countSky(f, model.radius_m(), model.radius_m() + 1.0, f.sun).lit, 0) << height;
  }
}

// From space the sky is drawn on a ring round the planet; the sun's disc in open space has its own
// square (terrain_sky.vert): looking straight up from 2e7 m with the sun at the zenith.
TEST_F(AtmosphereRenderTest, SunDiscIsDrawnInOpenSpace) {
  const Frame f = render(earthlikeModel(), {20.0, 30.0, 2.0e7, 0.0, 90.0, 0.0}, {0.0, 90.0});
  const auto pixel = [&](uint32_t x, uint32_t y) {
    const size_t i = size_t(y) * kWidth + x;
    return glm::dvec3(f.image.rgba[4 * i], f.image.rgba[4 * i + 1], f.image.rgba[4 * i + 2]);
  };
  const glm::dvec3 centre = pixel(kWidth / 2, kHeight / 2), aside = pixel(kWidth / 2 + kWidth / 8, kHeight / 2);
  std::printf("[ info ] sun from 2e7 m: (%.3f, %.3f, %.3f), beside it (%.3f, %.3f, %.3f)\n", centre.x, centre.y,
              centre.z, aside.x, aside.y, aside.z);
  EXPECT_GT(std::min({centre.x, centre.y, centre.z}), 0.9);
  EXPECT_EQ(aside, glm::dvec3(0.0));  // black space
  EXPECT_EQ(device().validation().count(), 0u);
}

// Mean linear colour of the background pixels in the band of rows [y0, y1) and columns [x0, x1).
glm::dvec3 meanSky(const Frame& f, uint32_t x0, uint32_t x1, uint32_t y0, uint32_t y1) {
  glm::dvec3 sum(0.0);
  int n = 0;
  for (uint32_t y = y0; y < y1; ++y) {
    for (uint32_t x = x0; x < x1; ++x) {
      const size_t i = size_t(y) * kWidth + x;
      if (std::isfinite(f.image.z[i])) continue;
      sum += glm::dvec3(f.image.rgba[4 * i], f.image.rgba[4 * i + 1], f.image.rgba[4 * i + 2]);
      ++n;
    }
  }
  EXPECT_GT(n, 20) << "too few sky pixels in the band";
  return n > 0 ? sum / double(n) : sum;
}

TEST_F(AtmosphereRenderTest, BlueSkyByDayRedTowardsTheSettingSun) {
  const ElevationModel& model = earthlikeModel();
  // Looking east a little upwards from 2 m over lowlands at 0 N 0 E (35 m above sea level; the
  // plateau at 7 km is above most of the haze): the band just above the horizon.
  const GeodeticPose pose{0.0, 0.0, 2.0, 90.0, 3.0, 0.0};
  const Frame day = render(model, pose, {270.0, 45.0});  // the sun behind the camera
  const uint32_t horizon = kHeight / 2 + 4;              // 3 degrees below the centre
  const glm::dvec3 blue = meanSky(day, 0, kWidth, horizon - 20, horizon);
  std::printf("[ info ] sun 45 degrees: sky (%.3f, %.3f, %.3f)\n", blue.x, blue.y, blue.z);
  EXPECT_GT(blue.z, blue.x);
  const Frame dusk = render(model, pose, {90.0, 2.0});  // the sun ahead, low
  const glm::dvec3 red = meanSky(dusk, kWidth / 4, 3 * kWidth / 4, horizon - 20, horizon);
  std::printf("[ info ] sun 2 degrees: sky towards it (%.3f, %.3f, %.3f)\n", red.x, red.y, red.z);
  EXPECT_GT(red.x, red.z);
}

// The `sky` detail of fast and balanced: the atmosphere's sky behind a terrain lit without the
// per-frame table (the terrain pipelines without the air's light), by the sun's and the sky's light
// over the ground below the camera (hazeGroundLight) and seen through the analytic haze
// (terrain_haze.glsl): within 100 m the colours of `full` (whose aerial perspective starts at 300 m),
// at noon and at dusk, where the air reddens the sun; from 10 km up, bluer than without the air.
TEST_F(AtmosphereRenderTest, SkyDetailDrawsTheSkyBehindTheTerrainOfNoAtmosphereThroughTheHaze) {
  const ElevationModel& model = earthlikeModel();
  const GeodeticPose pose{0.0, 0.0, 2.0, 90.0, 3.0, 0.0};
  const Frame off = render(model, pose, {270.0, 45.0}, {}, AtmosphereDetail::kOff);
  Frame sky;
  for (const double sunElevation : {6.0, 45.0}) {
    const Frame full = render(model, pose, {270.0, sunElevation}, {}, AtmosphereDetail::kFull);
    sky = render(
        model, pose, {270.0, sunElevation},
        [](Terrain& terrain, const Frame&) {
          EXPECT_NE(terrain.atmosphere(), nullptr);
          EXPECT_EQ(terrain.renderer().atmosphereView(), nullptr);
        },
        AtmosphereDetail::kSky);
    int nearPixels = 0;
    double largest = 0.0;
    glm::dvec3 mean(0.0);
    for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
      ASSERT_EQ(std::isfinite(full.image.z[i]), std::isfinite(sky.image.z[i])) << i;
      if (!(full.image.z[i] < 100.0)) continue;
      ++nearPixels;
      for (int c = 0; c < 3; ++c)
        largest = std::max(largest, double(std::abs(full.image.rgba[4 * i + c] - sky.image.rgba[4 * i + c])));
      mean += glm::dvec3(sky.image.rgba[4 * i], sky.image.rgba[4 * i + 1], sky.image.rgba[4 * i + 2]);
    }
    mean /= double(std::max(nearPixels, 1));
    std::printf(
        "[ info ] sun %.0f degrees: near ground sky vs full, largest difference %.4f, sky's mean %.3f %.3f %.3f\n",
        sunElevation, largest, mean.x, mean.y, mean.z);
    EXPECT_GT(nearPixels, 100);
    EXPECT_LT(largest, 2.0 / 255.0);  // measured 0.0022 at 6 degrees, 0.0032 at 45 (2026-12-07)
  }
  int terrainPixels = 0, skyPixels = 0;
  for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
    if (std::isfinite(off.image.z[i])) {
      ++terrainPixels;
    } else {
      ++skyPixels;
      EXPECT_EQ(off.image.rgba[4 * i + 2], 0.0f) << i;  // black space without the atmosphere
    }
  }
  EXPECT_GT(terrainPixels, 1000);
  EXPECT_GT(skyPixels, 1000);
  const uint32_t horizon = kHeight / 2 + 4;
  const glm::dvec3 blue = meanSky(sky, 0, kWidth, horizon - 20, horizon);
  EXPECT_GT(blue.z, blue.x);
  EXPECT_GT(blue.z, 0.1);
  // From 10 km, ground 10-100 km away: the haze takes the colours towards the air's blue.
  const GeodeticPose high{22.0, -98.8, 1.0e4, 60.0, -15.0, 0.0};
  const Frame offHigh = render(model, high, {270.0, 45.0}, {}, AtmosphereDetail::kOff);
  const Frame skyHigh = render(model, high, {270.0, 45.0}, {}, AtmosphereDetail::kSky);
  glm::dvec3 a(0.0), b(0.0);
  int ground = 0;
  for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
    if (!std::isfinite(offHigh.image.z[i])) continue;
    ++ground;
    a += glm::dvec3(offHigh.image.rgba[4 * i], offHigh.image.rgba[4 * i + 1], offHigh.image.rgba[4 * i + 2]);
    b += glm::dvec3(skyHigh.image.rgba[4 * i], skyHigh.image.rgba[4 * i + 1], skyHigh.image.rgba[4 * i + 2]);
  }
  ASSERT_GT(ground, 1000);
  a /= double(ground);
  b /= double(ground);
  std::printf("[ info ] from 10 km, mean ground: off %.3f %.3f %.3f, sky %.3f %.3f %.3f\n", a.x, a.y, a.z, b.x, b.y,
              b.z);
  EXPECT_GT(b.z / b.x, 1.2 * a.z / a.x);  // bluer
  EXPECT_GT(b.z, a.z);
  EXPECT_EQ(device().validation().count(), 0u);
}

// Standard deviation of the luminance of terrain pixels between `near_m` and `far_m` from the camera.
double terrainContrast(const Frame& f, double near_m, double far_m, int& count) {
  double sum = 0, sum2 = 0;
  count = 0;
  for (size_t i = 0; i < f.image.z.size(); ++i) {
    if (!(f.image.z[i] >= near_m && f.image.z[i] < far_m)) continue;
    const double l = 0.2126 * f.image.rgba[4 * i] + 0.7152 * f.image.rgba[4 * i + 1] + 0.0722 * f.image.rgba[4 * i + 2];
    sum += l;
    sum2 += l * l;
    ++count;
  }
  if (count == 0) return 0;
  const double mean = sum / count;
  return std::sqrt(std::max(sum2 / count - mean * mean, 0.0));
}

TEST_F(AtmosphereRenderTest, DistantMountainsHaveLessContrast) {
  const ElevationModel& model = earthlikeModel();
  // From 1.5 km over the plateau, looking down the range: ridges from 1.5 km to the horizon.
  const Frame f = render(model, {22.0, -98.4, 1500.0, 80.0, -15.0, 0.0}, {200.0, 35.0});
  int nearCount = 0, farCount = 0;
  const double nearContrast = terrainContrast(f, 1000.0, 3000.0, nearCount);
  const double farContrast = terrainContrast(f, 40000.0, 60000.0, farCount);
  std::printf("[ info ] contrast 1-3 km %.4f (%d px), 40-60 km %.4f (%d px)\n", nearContrast, nearCount, farContrast,
              farCount);
  ASSERT_GT(nearCount, 100);
  ASSERT_GT(farCount, 100);
  EXPECT_LT(farContrast, nearContrast);
}

// The aerial perspective of the per-frame table (AtmosphereView) against the exact evaluation, at
// every terrain pixel beyond 300 m (nearer, none is applied), in what reaches the screen: the
// exposed in-scattered light exposure * S (a scene value, displayed as it is below the display
// transform's knee, display_encoding.glsl) and the transmittance T, both in [0, 1].
struct TableError {
  std::vector<double> fog, transmittance;
};

TableError compareTable(vk::Device& device, Terrain& terrain, const Frame& f) {
  std::vector<float> points;
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      const double z = f.image.z[size_t(y) * kWidth + x];
      if (!(z > 300.0) || !std::isfinite(z)) continue;
      const glm::vec3 p(pixelRay(f.camera, x, y) * z);
      points.insert(points.end(), {p.x, p.y, p.z, 0.0f});
    }
  }
  TableError error;
  const uint32_t n = uint32_t(points.size() / 4);
  if (n == 0) return error;
  vk::Buffer in(device, n * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible, "test points");
  vk::Buffer out(device, n * 64, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible, "test results");
  std::copy(points.begin(), points.end(), static_cast<float*>(in.mapped()));
  const vk::ComputePipeline kernel(device, GLOBE_TEST_SHADER_DIR "/test_atmosphere_view.comp", 9, 0,
                                   (1u << 3) | (1u << 7));
  const AtmosphereLuts& luts = *terrain.atmosphere();
  const AtmosphereView& view = *terrain.renderer().atmosphereView();
  device.submitAndWait([&](VkCommandBuffer cmd) {
    terrain.prepare(cmd, f.camera, 0);
    kernel.bind(cmd,
                {in.descriptor(), out.descriptor(), in.descriptor(), luts.parameters(), luts.transmittance(),
                 luts.irradiance(), luts.scattering(), view.camera(0), view.table(0)},
                nullptr, 0);
    vkCmdDispatch(cmd, (n + 63) / 64, 1, 1);
    vk::computeWriteBarrier(cmd);
  });
  const float* r = static_cast<const float*>(out.mapped());
  const double exposure = luts.packed().misc.z;
  for (uint32_t i = 0; i < n; ++i, r += 16) {
    double fog = 0, transmittance = 0;
    for (int c = 0; c < 3; ++c) {
      fog = std::max(fog, exposure * std::abs(double(r[c]) - double(r[8 + c])));
      transmittance = std::max(transmittance, double(std::abs(r[4 + c] - r[12 + c])));
    }
    error.fog.push_back(fog);
    error.transmittance.push_back(transmittance);
  }
  return error;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(q * double(v.size())))];
}

// Within the table's reach (50 km) the terrain's vertices read the table, beyond it the exact
// evaluation: the errors are the table's, at every distance up to its reach and every altitude.
TEST_F(AtmosphereRenderTest, PerFrameTableMatchesTheExactEvaluation) {
  const ElevationModel& model = earthlikeModel();
  const View views[] = {
      {"2 m, noon", {22.0, -98.4, 2.0, 90.0, 0.0, 0.0}, {270.0, 45.0}},
      {"2 m, dusk", {22.0, -98.4, 2.0, 90.0, 0.0, 0.0}, {90.0, 2.0}},
      {"1.5 km", {22.0, -98.4, 1500.0, 80.0, -15.0, 0.0}, {200.0, 35.0}},
      {"10 km", {22.0, -98.4, 1.0e4, 90.0, -10.0, 0.0}, {90.0, 20.0}},
      {"100 km", {22.0, -98.4, 1.0e5, 90.0, -5.0, 0.0}, {90.0, 30.0}},
      {"2e7 m", {22.0, -98.4, 2.0e7, 0.0, -90.0, 0.0}, {90.0, 30.0}},
  };
  for (const View& v : views) {
    TableError e;
    render(model, v.pose, v.sun, [&](Terrain& terrain, const Frame& f) { e = compareTable(device(), terrain, f); });
    std::printf(
        "[ info ] %s: %zu points; |fog error| median %.4f, 99 %% %.4f, max %.4f; |transmittance error| "
        "median %.4f, 99 %% %.4f, max %.4f\n",
        v.name, e.fog.size(), percentile(e.fog, 0.5), percentile(e.fog, 0.99), percentile(e.fog, 1.0),
        percentile(e.transmittance, 0.5), percentile(e.transmittance, 0.99), percentile(e.transmittance, 1.0));
    EXPECT_GT(e.fog.size(), 1000u) << v.name;
    EXPECT_LT(percentile(e.fog, 0.5), 0.004) << v.name;
    EXPECT_LT(percentile(e.transmittance, 0.5), 0.004) << v.name;
    EXPECT_LT(percentile(e.fog, 0.99), 0.01) << v.name;
    EXPECT_LT(percentile(e.transmittance, 0.99), 0.01) << v.name;
    EXPECT_LT(percentile(e.fog, 1.0), 0.03) << v.name;
    EXPECT_LT(percentile(e.transmittance, 1.0), 0.03) << v.name;
  }
}

}  // namespace
}  // namespace globe::testing
