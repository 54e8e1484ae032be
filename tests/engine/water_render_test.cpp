// The sea of a planet with [water]: a surface at sea level over lower ground, shaded per fragment
// (terrain_water.frag), with cameras placed above it.
#include "engine/io/image_io.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/quality.h"
#include "engine/render/render_output.h"
#include "planet/geometry/triacontahedron.h"
#include "tests/support/gpu_test.h"

#include <cmath>

namespace globe::testing {
namespace {

class WaterRenderTest : public GpuTest {
 protected:
  ImageRgba render(const GeodeticPose& pose, uint32_t width, uint32_t height) {
    TerrainSettings settings;
    settings.gridCells = 16;
    return render(pose, width, height, settings);
  }
  ImageRgba render(const GeodeticPose& pose, uint32_t width, uint32_t height, const TerrainSettings& settings) {
    const ElevationModel& model = earthlikeModel();
    auto terrain = Terrain::create(device(), model, settings);
    EXPECT_TRUE(terrain.ok()) << terrain.error().format();
    HeadlessRenderer renderer(device(), {width, height});
    const glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
    const Camera camera =
        cameraFromPose(pose, (*terrain)->cameraGroundRadius(down), model.radius_m(), double(width) / height);
    renderer.renderFrame(**terrain, camera, true);
    return toImage(renderer.readback(), camera);
  }
};

float luminance(const ImageRgba& image, uint32_t x, uint32_t y) {
  const float* p = &image.rgba[(size_t(y) * image.width + x) * 4];
  return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

// 10 cm above the open sea (the ground is ~2 km below): the camera stands above the water, every
// pixel below the horizon is sea (no sky through it), the sea at its feet is the water's own dark
// colour, and it brightens towards the horizon as the reflected sky takes over (Fresnel).
TEST_F(WaterRenderTest, TenCentimetresAboveTheSea) {
  ASSERT_LT(earthlikeModel().elevation_m(directionFromLatLon(45.0, 7.0)), -1000.0);
  const ImageRgba image = render({45.0, 7.0, 0.1, 0.0, -10.0, 0.0}, 160, 120);
  int uncovered = 0;
  for (uint32_t y = image.height * 3 / 4; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) uncovered += !std::isfinite(image.z[size_t(y) * image.width + x]);
  EXPECT_EQ(uncovered, 0);
  const float* feet = &image.rgba[(size_t(image.height - 1) * image.width + image.width / 2) * 4];
  std::printf("[ info ] sea at the feet (%.3f, %.3f, %.3f), luminance %.3f; 10 rows lower than the horizon %.3f\n",
              feet[0], feet[1], feet[2], luminance(image, image.width / 2, image.height - 1),
              luminance(image, image.width / 2, image.height / 2 + 10));
  EXPECT_GT(feet[2], feet[0]);                                           // blue, not sand
  EXPECT_LT(luminance(image, image.width / 2, image.height - 1), 0.1f);  // not the sky (~0.5)
  EXPECT_LT(luminance(image, image.width / 2, image.height - 1),
            luminance(image, image.width / 2, image.height / 2 + 10));
}

// A coast seen from 40 km: both sea and land fill large parts of the view, and every pixel is one or
// the other (the coast is decided per fragment, so no band of blended colours lines it).
TEST_F(WaterRenderTest, CoastFromFortyKilometres) {
  const ImageRgba image = render({23.0, 11.0, 40000.0, 200.0, -40.0, 0.0}, 160, 120);
  int sea = 0, land = 0;
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      if (!std::isfinite(image.z[size_t(y) * image.width + x])) continue;
      const float* p = &image.rgba[(size_t(y) * image.width + x) * 4];
      // Through 40 km of air (full atmosphere) the land's green takes a blue tint: the sea is the
      // clearly blue pixels (blue over 1.5 x green in linear light: ~2 there, ~1.1 over the land).
      sea += p[2] > p[0] && p[2] > 1.5f * p[1];
      land += p[2] < 1.3f * p[1];
    }
  }
  std::printf("[ info ] coast: %d sea and %d land pixels of %u\n", sea, land, image.width * image.height);
  EXPECT_GT(sea, int(image.width * image.height) / 20);
  EXPECT_GT(land, int(image.width * image.height) / 5);
}

// The default preset's beach seen from 20 km (the coast camera of docs/rendering.md's gallery, its
// ground alone): its surface texels carry the luma, its vertices (every 4 texels) the hue as a ratio
// to luma. A band of sand a texel or two wide between vegetation vertices took the vegetation's ratio
// at the sand's luma, a bright green no class has, in teeth along the coast; where a texel is much
// brighter than its vertices the fragment now drops their hue (terrain_fragment.glsl). Bright pixels
// (display luma over 120/255) greener than (r + b) / 2 by 30/255: 635 before, 0 after, 0 under
// `exact` (its vertices are its texels), 320 x 180, 2026-12-08.
TEST_F(WaterRenderTest, BalancedBeachTakesNoHueOfTheVegetationBesideIt) {
  TerrainSettings settings = terrainSettingsFor(QualityPreset::kBalanced);
  settings.atmosphere = AtmosphereDetail::kOff;
  settings.viewHeight_px = 180;
  const GeodeticPose pose{16.9, -107.3, 20000.0, 60.0, -25.0, 0.0};
  // globe render's sun for the camera.
  settings.style.sunDirection = defaultSunDirection(directionFromLatLon(pose.latitude_deg, pose.longitude_deg));
  const ImageRgba image = render(pose, 320, 180, settings);
  int bright = 0, green = 0;
  for (size_t i = 0; i < size_t(image.width) * image.height; ++i) {
    if (!std::isfinite(image.z[i])) continue;
    // The PNG's bytes.
    const float r = linearToSrgb8(image.rgba[4 * i]), g = linearToSrgb8(image.rgba[4 * i + 1]),
                b = linearToSrgb8(image.rgba[4 * i + 2]);
    if (0.2126f * r + 0.7152f * g + 0.0722f * b <= 120.0f) continue;
    ++bright;
    green += g - 0.5f * (r + b) > 30.0f;
  }
  std::printf("[ info ] beach: %d of %d bright ground pixels bright green\n", green, bright);
  EXPECT_GT(bright, 200);
  EXPECT_LE(green, 10);
}

}  // namespace
}  // namespace globe::testing
