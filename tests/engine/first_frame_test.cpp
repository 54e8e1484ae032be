// A planet from the first frame: the terrain's warm-up (TerrainSettings::primeRounds) makes the 30
// roots and the first view resident before frame 0 is drawn, so a budgeted run never starts black.
#include "engine/render/headless_renderer.h"
#include "engine/render/render_output.h"
#include "planet/geometry/triacontahedron.h"
#include "tests/support/gpu_test.h"

#include <cmath>

namespace globe::testing {
namespace {

class FirstFrameTest : public GpuTest {};

constexpr uint32_t kWidth = 160, kHeight = 120;

// The whole disc in view: 2 radii above the ground, looking straight down.
Camera wholePlanetCamera(const ElevationModel& model) {
  const GeodeticPose pose{20.0, 10.0, 2.0 * model.radius_m(), 0, -90, 0};
  const glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
  return cameraFromPose(pose, model.radius_m() + model.elevation_m(down), model.radius_m(), double(kWidth) / kHeight);
}

// Pixels whose ray hits a sphere slightly inside the lowest ground (away from the silhouette, so
// sub-pixel edge effects don't count), and how many of them the terrain covered (finite depth).
struct Coverage {
  int inside = 0;
  int covered = 0;
};

Coverage silhouetteCoverage(const ImageRgba& image, const Camera& camera, double innerRadius_m) {
  Coverage c;
  const double tanHalf = std::tan(camera.verticalFov_rad / 2);
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      const double sx = (2.0 * (x + 0.5) / image.width - 1.0) * tanHalf * camera.aspect;
      const double sy = (1.0 - 2.0 * (y + 0.5) / image.height) * tanHalf;
      const glm::dvec3 ray = glm::normalize(camera.forward + sx * camera.right + sy * camera.up);
      const double b = glm::dot(camera.position_m, ray);
      const double disc = b * b - (glm::dot(camera.position_m, camera.position_m) - innerRadius_m * innerRadius_m);
      if (disc <= 0) continue;
      ++c.inside;
      if (std::isfinite(image.z[size_t(y) * image.width + x])) ++c.covered;
    }
  }
  return c;
}

TEST_F(FirstFrameTest, BudgetedFrameZeroDrawsTheWholePlanet) {
  const ElevationModel& model = earthlikeModel();
  TerrainSettings settings;
  settings.gridCells = 16;
  settings.style.sky = false;
  auto terrain = Terrain::create(device(), model, settings);
  ASSERT_TRUE(terrain.ok()) << terrain.error().format();
  HeadlessRenderer renderer(device(), {kWidth, kHeight});
  const Camera camera = wholePlanetCamera(model);

  const FrameStats stats = renderer.renderFrame(**terrain, camera, false);  // budgeted: no waiting
  std::printf("[ info ] frame 0 after %u warm-up rounds: %u nodes, %llu triangles\n", (*terrain)->primedRounds(),
              stats.nodes_selected, static_cast<unsigned long long>(stats.triangles));
  EXPECT_GE(stats.nodes_selected, 30u);
  for (int face = 0; face < kFaceCount; ++face)
    EXPECT_TRUE((*terrain)->pool().slotOf(NodeId{uint8_t(face), 0, 0, 0}).has_value()) << "root " << face;

  const ImageRgba image = toImage(renderer.readback(), camera);
  const Coverage c = silhouetteCoverage(image, camera, 0.99 * (model.radius_m() + model.bounds().min_m));
  ASSERT_GT(c.inside, int(kWidth * kHeight / 10));
  EXPECT_EQ(c.covered, c.inside) << "pixels inside the planet's silhouette left empty";
}

TEST_F(FirstFrameTest, WithoutWarmUpFrameZeroIsEmpty) {
  // The contrast that makes the test above meaningful: a cold terrain has nothing resident yet.
  const ElevationModel& model = earthlikeModel();
  TerrainSettings settings;
  settings.gridCells = 16;
  settings.style.sky = false;
  settings.primeRounds = 0;
  auto terrain = Terrain::create(device(), model, settings);
  ASSERT_TRUE(terrain.ok()) << terrain.error().format();
  HeadlessRenderer renderer(device(), {kWidth, kHeight});
  const FrameStats stats = renderer.renderFrame(**terrain, wholePlanetCamera(model), false);
  EXPECT_EQ(stats.nodes_selected, 0u);
}

}  // namespace
}  // namespace globe::testing
