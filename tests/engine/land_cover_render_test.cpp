// Land cover on screen: earthlike seen from orbit shows its classes (the land cover debug view draws
// each vertex in its dominant class's key colour), and the shaded view splats the detail textures.
#include "engine/render/headless_renderer.h"
#include "engine/render/render_output.h"
#include "planet/geometry/triacontahedron.h"
#include "tests/support/gpu_test.h"

#include <array>
#include <cmath>

namespace globe::testing {
namespace {

class LandCoverRenderTest : public GpuTest {
 protected:
  ImageRgba render(const GeodeticPose& pose, TerrainDebugView view, uint32_t width, uint32_t height,
                   const ElevationModel& model = earthlikeModel()) {
    TerrainSettings settings;
    settings.gridCells = 16;
    settings.detailTextures = detail_;
    settings.style.debug = view;
    const glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
    settings.style.sunDirection = down;  // the sun overhead
    auto terrain = Terrain::create(device(), model, settings);
    EXPECT_TRUE(terrain.ok()) << terrain.error().format();
    HeadlessRenderer renderer(device(), {width, height});
    const Camera camera = cameraFromPose(pose, model.radius_m() + model.visibleElevation_m(down), model.radius_m(),
                                         double(width) / height);
    renderer.renderFrame(**terrain, camera, true);
    return toImage(renderer.readback(), camera);
  }
  DetailTextures detail_ = DetailTextures::kOn;
};

// The key colour of class i (terrain_level_colour.glsl: level i's), linear.
glm::vec3 keyColour(int i) {
  const float hue = std::fmod(float(i) * 0.618034f, 1.0f);
  glm::vec3 k;
  for (int c = 0; c < 3; ++c) {
    const float offset = c == 0 ? 0.0f : c == 1 ? 2.0f / 3.0f : 1.0f / 3.0f;
    const float f = std::fmod(hue + offset, 1.0f);
    k[c] = std::clamp(std::abs(f * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
  }
  return glm::mix(glm::vec3(0.15f), k, 0.85f);
}

TEST_F(LandCoverRenderTest, EarthlikeFromOrbitShowsAtLeastFiveClasses) {
  const ElevationModel& model = earthlikeModel();
  ASSERT_GE(model.landCover().class_count, 5u) << "earthlike has no land cover";
  // Over the continent of the default flight, the whole disc in view.
  const ImageRgba image = render({17.0, -106.0, 1.5e7, 0.0, -90.0, 0.0}, TerrainDebugView::kLandCover, 320, 240);
  std::array<int, 8> pixels{};
  int disc = 0;
  for (size_t p = 0; p < size_t(image.width) * image.height; ++p) {
    if (!std::isfinite(image.z[p])) continue;
    ++disc;
    const glm::vec3 c(image.rgba[p * 4], image.rgba[p * 4 + 1], image.rgba[p * 4 + 2]);
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 d = c - keyColour(i);
      if (glm::dot(d, d) < 0.02f * 0.02f * 3.0f) ++pixels[size_t(i)];
    }
  }
  int shown = 0;
  for (int i = 0; i < int(model.landCover().class_count); ++i) {
    std::printf("[ info ] class %d: %d of %d disc pixels\n", i, pixels[size_t(i)], disc);
    shown += pixels[size_t(i)] >= disc / 500;  // 0.2 % of the disc
  }
  EXPECT_GT(disc, 10000);
  EXPECT_GE(shown, 5);
}

// Mean absolute difference between horizontally adjacent pixels' green in the lower half (the ground).
double groundVariation(const ImageRgba& image) {
  double sum = 0.0;
  int count = 0;
  for (uint32_t y = image.height / 2; y < image.height; ++y) {
    for (uint32_t x = 1; x < image.width; ++x) {
      const float* a = &image.rgba[(size_t(y) * image.width + x) * 4];
      sum += std::abs(a[1] - a[-3]);
      ++count;
    }
  }
  return sum / count;
}

// 2 m above the ground: the splat's detail textures vary the colour within what one class covers;
// with flat textures (contrast 0) the same view is the smooth blend of the vertices' colours.
TEST_F(LandCoverRenderTest, DetailTexturesVaryTheGroundAtTwoMetres) {
  auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
  ASSERT_TRUE(planet.ok());
  for (LandCoverClass& c : planet->land_cover.classes) c.detail_contrast = 0.0;
  const ElevationModel flat(*planet);
  const GeodeticPose pose{17.08, -106.55, 2.0, 80.0, -30.0, 0.0};
  const double textured = groundVariation(render(pose, TerrainDebugView::kShaded, 160, 120));
  const double smooth = groundVariation(render(pose, TerrainDebugView::kShaded, 160, 120, flat));
  std::printf("[ info ] mean neighbour difference of the ground's green: %.4f textured, %.4f flat\n", textured, smooth);
  EXPECT_GT(textured, 1.5 * smooth);
}

// The balanced preset's ground detail (DetailTextures::kNear): the splat on the nodes near the camera
// only, faded out with view depth. At 2 m it varies the ground as the splat everywhere does; from
// 1 km the image is the one without the splat, bit for bit (the nodes drawn with it, if any, are
// faded out completely, and the others are drawn as without it).
TEST_F(LandCoverRenderTest, GroundDetailNearTheCameraOnly) {
  const GeodeticPose ground{17.08, -106.55, 2.0, 80.0, -30.0, 0.0};
  const GeodeticPose high{22.05, -98.4, 1000.0, 60.0, -8.0, 0.0};
  detail_ = DetailTextures::kOff;
  const double without = groundVariation(render(ground, TerrainDebugView::kShaded, 160, 120));
  const ImageRgba highWithout = render(high, TerrainDebugView::kShaded, 160, 120);
  detail_ = DetailTextures::kNear;
  const double near = groundVariation(render(ground, TerrainDebugView::kShaded, 160, 120));
  const ImageRgba highNear = render(high, TerrainDebugView::kShaded, 160, 120);
  std::printf("[ info ] mean neighbour difference of the ground's green at 2 m: %.4f near, %.4f without\n", near,
              without);
  EXPECT_GT(near, 1.5 * without);
  EXPECT_TRUE(highNear.rgba == highWithout.rgba) << "the splat changed the view from 1 km";
}

}  // namespace
}  // namespace globe::testing
