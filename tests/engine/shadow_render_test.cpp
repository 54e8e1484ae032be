// Cast shadows of the relief (engine/render/terrain_shadows.h): at dusk, ground that the CPU
// reference finds behind relief as seen from the sun is drawn darker than ground the sun reaches,
// though both face the sun, and darker than it is drawn without shadows.
#include "engine/render/headless_renderer.h"
#include "engine/render/render_output.h"
#include "engine/render/shadow_cascades.h"
#include "engine/render/terrain_shadows.h"
#include "tests/support/gpu_test.h"

#include <cmath>

namespace globe::testing {
namespace {

constexpr uint32_t kWidth = 192, kHeight = 108;
// Hills seen from 1 km at dusk: the sun 8 degrees up, 30 degrees right of the view.
constexpr GeodeticPose kPose{22.05, -98.4, 1000.0, 60.0, -8.0, 0.0};
constexpr SunAngles kDusk{90.0, 8.0};
// The same hills looking down and away from a sun 5 degrees up behind the camera: the relief that
// shades the near ground lies outside the view (shadow_casters.h).
constexpr GeodeticPose kPoseDown{22.05, -98.4, 1000.0, 60.0, -25.0, 0.0};
constexpr SunAngles kBehind{250.0, 5.0};

struct Frame {
  ImageRgba image;
  Camera camera;
  glm::dvec3 sun{0.0};
  std::array<uint32_t, kShadowCascades> casters{};
};

Frame render(vk::Device& device, const GeodeticPose& pose, const SunAngles& sunAngles, bool shadows) {
  const ElevationModel& model = earthlikeModel();
  TerrainSettings settings;
  settings.gridCells = 32;
  settings.normalMapScale = 1;
  settings.atmosphere = AtmosphereDetail::kOff;  // Lambert and ambient: what the sun adds is plain
  settings.shadows = shadows;
  const glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
  settings.style.sunDirection = sunDirectionAt(down * model.radius_m(), sunAngles);
  auto terrain = Terrain::create(device, model, settings);
  EXPECT_TRUE(terrain.ok()) << terrain.error().format();
  HeadlessRenderer renderer(device, {kWidth, kHeight});
  Frame f;
  f.camera = cameraFromPose(pose, (*terrain)->cameraGroundRadius(down), model.radius_m(), double(kWidth) / kHeight);
  renderer.renderFrame(**terrain, f.camera, true);
  f.image = toImage(renderer.readback(), f.camera);
  f.sun = glm::normalize(settings.style.sunDirection);
  if (const TerrainShadows* s = (*terrain)->renderer().shadows()) f.casters = s->casters();
  return f;
}

// The ground point a pixel shows (planet-fixed metres), from its ray distance.
glm::dvec3 groundAt(const Frame& f, uint32_t x, uint32_t y) {
  const Camera& c = f.camera;
  const double tanY = std::tan(c.verticalFov_rad * 0.5);
  const double nx = (x + 0.5) / kWidth * 2.0 - 1.0, ny = (y + 0.5) / kHeight * 2.0 - 1.0;
  const glm::dvec3 ray = glm::normalize(c.forward + c.right * (nx * tanY * c.aspect) - c.up * (ny * tanY));
  return c.position_m + ray * double(f.image.z[size_t(y) * kWidth + x]);
}

// How the sun reaches a ground point in the CPU reference: facing it (its normal from the
// elevation's differences 10 m apart), and the least clearance (metres) of the ray towards it over
// the terrain from 60 m to 20 km (< 0: the relief stands in the way).
struct SunReach {
  double cosSun = 0.0;
  double clearance_m = 0.0;
};

SunReach sunReach(const ElevationModel& model, const glm::dvec3& p, const glm::dvec3& sun) {
  const glm::dvec3 up = glm::normalize(p);
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), up)), north = glm::cross(up, east);
  auto surface = [&](const glm::dvec3& q) {
    const glm::dvec3 d = glm::normalize(q);
    return d * (model.radius_m() + model.visibleElevation_m(d));
  };
  const glm::dvec3 n = glm::normalize(glm::cross(surface(p + east * 10.0) - surface(p - east * 10.0),
                                                 surface(p + north * 10.0) - surface(p - north * 10.0)));
  SunReach r{glm::dot(n, sun), 1e30};
  for (double t = 60.0; t <= 20000.0; t *= 1.15) {
    const glm::dvec3 q = p + sun * t;
    r.clearance_m = std::min(r.clearance_m, glm::length(q) - glm::length(surface(q)));
  }
  return r;
}

float luminance(const ImageRgba& image, uint32_t x, uint32_t y) {
  const float* p = &image.rgba[(size_t(y) * image.width + x) * 4];
  return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

// The cascades' boxes: ground ahead of the camera inside the finest, depth decreasing towards the
// sun, radii in steps of kShadowCascadeRatio; none from high up or with the sun set.
TEST(ShadowCascades, BoxesHoldTheGroundAndLookAlongTheSunlight) {
  const double radius_m = 6371000.0;
  const glm::dvec3 down = directionFromLatLon(10.0, 20.0);
  const Camera camera = cameraFromPose({10.0, 20.0, 1000.0, 30.0, -10.0, 0.0}, radius_m, radius_m, 16.0 / 9.0);
  const glm::dvec3 sun = sunDirectionAt(down * radius_m, {120.0, 10.0});
  ShadowView view{&camera, sun, radius_m, {radius_m - 11000.0, radius_m + 9000.0}, 2048};
  const ShadowCascades c = fitShadowCascades(view);
  ASSERT_EQ(c.count, 3u);
  EXPECT_EQ(c.cascades[0].radius_m, 4096.0);  // 2.5 x 1 km, up to a power of two
  EXPECT_EQ(c.cascades[1].radius_m, 4096.0 * kShadowCascadeRatio);
  for (uint32_t k = 0; k < c.count; ++k) {
    const glm::dvec3 ahead = down * radius_m + glm::normalize(camera.forward - down * glm::dot(camera.forward, down)) *
                                                   (0.5 * c.cascades[k].radius_m);
    const glm::dvec4 p = c.cascades[k].clipFromCamera * glm::dvec4(ahead - camera.position_m, 1.0);
    EXPECT_LT(std::max(std::abs(p.x), std::abs(p.y)), 0.5) << k;
    EXPECT_GT(p.z, 0.0) << k;
    EXPECT_LT(p.z, 1.0) << k;
    const glm::dvec4 sunward = c.cascades[k].clipFromCamera * glm::dvec4(ahead + sun * 100.0 - camera.position_m, 1.0);
    EXPECT_LT(sunward.z, p.z) << k;
    EXPECT_NEAR(sunward.x, p.x, 1e-9) << k;  // on the same light ray
    EXPECT_GT(c.cascades[k].texel_m, 0.0);
  }
  Camera high = camera;
  high.position_m = down * (radius_m + 2.0 * kShadowMaxHeight_m);
  view.camera = &high;
  EXPECT_EQ(fitShadowCascades(view).count, 0u);
  view.camera = &camera;
  view.sun = sunDirectionAt(down * radius_m, {120.0, -10.0});
  EXPECT_EQ(fitShadowCascades(view).count, 0u);
}

class ShadowRenderTest : public GpuTest {};

// Renders `pose` under `sun` with and without shadows and compares the pixels facing the sun
// (cos > 0.3), classed by the CPU reference: the sun clears the relief by 30 m or more, or relief
// stands 30 m or more in its way (the drawn mesh is coarser than the reference; the margin keeps the
// classes apart). Rows from `firstRow` down.
void expectReliefShadows(vk::Device& device, const GeodeticPose& pose, const SunAngles& sun, uint32_t firstRow) {
  const Frame lit = render(device, pose, sun, false), shaded = render(device, pose, sun, true);
  EXPECT_GT(shaded.casters[0], 0u);
  double sums[2][2]{};  // [shadowed by relief?][with shadows?]
  int counts[2]{};
  for (uint32_t y = firstRow; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      if (!std::isfinite(lit.image.z[size_t(y) * kWidth + x])) continue;
      const SunReach r = sunReach(earthlikeModel(), groundAt(lit, x, y), lit.sun);
      if (r.cosSun < 0.3 || std::abs(r.clearance_m) < 30.0) continue;
      const int behind = r.clearance_m < 0.0 ? 1 : 0;
      sums[behind][0] += luminance(lit.image, x, y);
      sums[behind][1] += luminance(shaded.image, x, y);
      ++counts[behind];
    }
  }
  std::printf("[ info ] casters per cascade %u %u %u; %d sunlit and %d shadowed pixels facing the sun\n",
              shaded.casters[0], shaded.casters[1], shaded.casters[2], counts[0], counts[1]);
  ASSERT_GE(counts[0], 100);
  ASSERT_GE(counts[1], 100);
  const double sunlitOff = sums[0][0] / counts[0], behindOff = sums[1][0] / counts[1];
  const double sunlitOn = sums[0][1] / counts[0], behindOn = sums[1][1] / counts[1];
  std::printf("[ info ] mean luminance without shadows: sunlit %.4f, behind relief %.4f; with: %.4f, %.4f\n", sunlitOff,
              behindOff, sunlitOn, behindOn);
  EXPECT_LT(behindOn, 0.5 * sunlitOn);   // in shadow: much darker than the lit slopes
  EXPECT_LT(behindOn, 0.5 * behindOff);  // and than without shadows
  EXPECT_GT(sunlitOn, 0.9 * sunlitOff);  // the lit slopes stay lit
}

TEST_F(ShadowRenderTest, AtDuskGroundBehindARidgeIsDarkerThanTheLitSlope) {
  expectReliefShadows(device(), kPose, kDusk, kHeight / 3);
}

// The bottom third of a view looking away from the sun: its shadows come from relief behind the camera.
TEST_F(ShadowRenderTest, ReliefBehindTheCameraShadesTheNearGround) {
  expectReliefShadows(device(), kPoseDown, kBehind, 2 * kHeight / 3);
}

}  // namespace
}  // namespace globe::testing
