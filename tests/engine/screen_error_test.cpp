// The screen-space error metric (engine/render/frame_screen_error.h) and its ground truth
// (planet/analysis/surface_ray.h): the ray caster against analytic ray-sphere intersections, the metric against
// injected errors, and a rendered frame of a sphere-shaped planet against its exact surface.
#include "engine/render/frame_screen_error.h"
#include "engine/render/headless_renderer.h"
#include "planet/analysis/surface_ray.h"
#include "planet/model/planet_file.h"
#include "tests/support/gpu_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace globe {
namespace {

// A planet whose only layer has zero amplitude: exactly a sphere of radius R.
PlanetDescription spherePlanet(double radius_m) {
  PlanetDescription p;
  p.name = "sphere";
  p.radius_m = radius_m;
  ElevationLayer flat;
  flat.name = "flat";
  flat.octaves = 1;
  flat.wavelength_m = 1000.0;
  flat.amplitude_m = 0.0;
  p.layers = {flat};
  return p;
}

// Distance to the sphere along a unit ray, +inf when it misses.
double raySphere(const glm::dvec3& o, const glm::dvec3& d, double radius) {
  double b = glm::dot(o, d), c = glm::dot(o, o) - radius * radius;
  double disc = b * b - c;
  if (disc < 0) return std::numeric_limits<double>::infinity();
  double t = -b - std::sqrt(disc);
  return t >= 0 ? t : std::numeric_limits<double>::infinity();
}

Camera cameraAbove(const ElevationModel& model, double height_m, double pitch_deg, double aspect) {
  GeodeticPose pose{22.0, -98.8, height_m, 60, pitch_deg, 0};
  glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
  return cameraFromPose(pose, model.radius_m() + model.elevation_m(down), model.radius_m(), aspect);
}

TEST(SurfaceRay, MatchesRaySphereToOneMillimetre) {
  ElevationModel model(spherePlanet(6371000.0));
  EXPECT_EQ(elevationSlopeBound(model.params()), 0.0);
  for (double height : {2.0, 1000.0, 1.0e5, 2.0e7}) {
    Camera camera = cameraAbove(model, height, height > 1.0e4 ? -60 : -5, 16.0 / 9.0);
    SurfaceTruth truth = castSurfaceTruth(model, camera, 64, 36, 1);
    uint32_t hits = 0, sky = 0;
    for (uint32_t r = 0; r < truth.rows; ++r)
      for (uint32_t c = 0; c < truth.columns; ++c) {
        glm::dvec3 dir = pixelRay(camera, 64, 36, truth.pixelX(c), truth.pixelY(r));
        double exact = raySphere(camera.position_m, dir, model.radius_m());
        const SurfaceRayHit& hit = truth.at(c, r);
        ASSERT_NE(hit.kind, SurfaceRayHit::Kind::kUnresolved);
        ASSERT_EQ(hit.kind == SurfaceRayHit::Kind::kHit, std::isfinite(exact))
            << height << " m, pixel " << c << "," << r;
        if (!std::isfinite(exact)) {
          ++sky;
          continue;
        }
        ++hits;
        EXPECT_NEAR(hit.distance_m, exact, 1.0e-3) << height << " m";
        glm::dvec3 p = camera.position_m + exact * dir;
        EXPECT_GT(glm::dot(hit.normal, glm::normalize(p)), 1.0 - 1e-9);
      }
    EXPECT_GT(hits, 0u) << height;
  }
}

TEST(SurfaceRay, HitsOfRealTerrainLieOnTheSurfaceAndNothingIsCrossedBefore) {
  auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
  ASSERT_TRUE(planet.ok());
  ElevationModel model(*planet);
  SurfaceRayCaster caster(model);
  EXPECT_GT(caster.slopeBound(), 1.0);
  Camera camera = cameraAbove(model, 1000.0, -8, 16.0 / 9.0);
  SurfaceRayOptions options;
  options.pixelAngle_rad = camera.verticalFov_rad / 36.0;
  for (double y : {20.0, 28.0, 35.0})
    for (double x : {0.0, 31.0, 63.0}) {
      glm::dvec3 dir = pixelRay(camera, 64, 36, x, y);
      SurfaceRayHit hit = caster.cast(camera.position_m, dir, options);
      ASSERT_EQ(hit.kind, SurfaceRayHit::Kind::kHit);
      glm::dvec3 p = camera.position_m + hit.distance_m * dir;
      double height = glm::length(p) - model.radius_m() - model.elevation_m(glm::normalize(p));
      EXPECT_LT(std::abs(height), 2.0e-3 * (1.0 + caster.slopeBound()));
      // Dense check before the hit: the ray stays above the ground (1 m samples).
      for (double t = 0; t < hit.distance_m - 1.0; t += 1.0) {
        glm::dvec3 q = camera.position_m + t * dir;
        ASSERT_GT(glm::length(q) - model.radius_m() - model.elevation_m(glm::normalize(q)), 0.0) << t;
      }
    }
}

TEST(ScreenError, InjectedErrorsAreMeasured) {
  ElevationModel model(spherePlanet(6371000.0));
  const uint32_t w = 96, h = 54;
  Camera camera = cameraAbove(model, 1000.0, -10, double(w) / h);
  SurfaceTruth truth = castSurfaceTruth(model, camera, w, h, 1);
  std::vector<double> exact(size_t(w) * h, std::numeric_limits<double>::infinity());
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      if (truth.at(x, y).kind == SurfaceRayHit::Kind::kHit) exact[size_t(y) * w + x] = truth.at(x, y).distance_m;

  ScreenError none = measureScreenError(truth, exact, camera);
  EXPECT_EQ(none.samples, w * h);
  EXPECT_GT(none.bothHit, w * h / 4);
  EXPECT_EQ(none.max_m, 0.0);
  EXPECT_LT(none.max_px, 1e-6);
  EXPECT_EQ(none.silhouetteMismatches, 0u);

  // Every hit 1 % too far: the metres error is 1 % of the distance; in pixels, the rendered point
  // sits 1 % · t · sin(a) above/below the plane, seen at t: about 0.01 · sin(a) · cos(a) rad.
  std::vector<double> far = exact;
  double maxExpected_m = 0;
  for (double& t : far)
    if (std::isfinite(t)) {
      maxExpected_m = std::max(maxExpected_m, 0.01 * t);
      t *= 1.01;
    }
  ScreenError e = measureScreenError(truth, far, camera);
  EXPECT_NEAR(e.max_m, maxExpected_m, 1e-6 * maxExpected_m);
  double pixelAngle = camera.verticalFov_rad / h;
  // The steepest ray meets the plane at < 50° here: under 0.01 · ½ rad.
  EXPECT_GT(e.p50_px, 0.0);
  EXPECT_LT(e.max_px, 0.005 / pixelAngle * 1.05);
  // Direct check at one pixel, the bottom centre (steepest).
  {
    uint32_t x = w / 2, y = h - 1;
    glm::dvec3 dir = pixelRay(camera, w, h, x, y);
    const SurfaceRayHit& hit = truth.at(x, y);
    double sinA = -glm::dot(dir, hit.normal);
    double expected = std::atan(0.01 * sinA * std::sqrt(1 - sinA * sinA) / (1.0 + 0.01 * sinA * sinA)) / pixelAngle;
    std::vector<double> one = exact;
    one[size_t(y) * w + x] *= 1.01;
    ScreenError single = measureScreenError(truth, one, camera);
    EXPECT_NEAR(single.max_px, expected, 0.02 * expected);
  }

  // Three rows of ground rendered as sky below the horizon: mismatches, and the rendered silhouette
  // is at most 3 px from each of them.
  std::vector<double> holes = exact;
  uint32_t firstGroundRow = h;
  for (uint32_t y = 0; y < h && firstGroundRow == h; ++y)
    if (std::isfinite(exact[size_t(y) * w + w / 2])) firstGroundRow = y;
  ASSERT_LT(firstGroundRow + 3, h);
  uint32_t removed = 0;
  for (uint32_t y = firstGroundRow; y < firstGroundRow + 3; ++y)
    for (uint32_t x = 0; x < w; ++x)
      if (std::isfinite(holes[size_t(y) * w + x])) {
        holes[size_t(y) * w + x] = std::numeric_limits<double>::infinity();
        ++removed;
      }
  ScreenError s = measureScreenError(truth, holes, camera);
  EXPECT_EQ(s.silhouetteMismatches, removed);
  EXPECT_GE(s.silhouetteMax_px, 1.0);
  EXPECT_LE(s.silhouetteMax_px, 3.0 + 1e-9);
}

class ScreenErrorGpuTest : public testing::GpuTest {};

TEST_F(ScreenErrorGpuTest, RenderedSphereIsWithinAFractionOfAPixel) {
  ElevationModel model(spherePlanet(6371000.0));
  const uint32_t w = 160, h = 90;
  HeadlessRenderer renderer(device(), {w, h});
  for (double height : {1000.0, 1.0e5}) {
    Camera camera = cameraAbove(model, height, -10, double(w) / h);
    TerrainSettings settings;
    settings.style.sunDirection = defaultSunDirection(camera.position_m);
    auto terrain = Terrain::create(device(), model, settings);
    ASSERT_TRUE(terrain.ok()) << terrain.error().format();
    renderer.renderFrame(**terrain, camera, true);
    SurfaceTruth truth = castSurfaceTruth(model, camera, w, h, 2);
    ScreenError e = measureScreenError(truth, renderer.readback(), camera);
    EXPECT_GT(e.bothHit, e.samples / 4) << height;
    EXPECT_EQ(e.unresolved, 0u);
    EXPECT_LT(e.p95_px, 0.1) << height;
    EXPECT_LT(e.max_px, 0.5) << height;
    // Only the horizon row can disagree (its pixel centre may fall either side of a chord).
    EXPECT_LE(e.silhouetteMismatches, truth.columns) << height;
    EXPECT_LE(e.silhouetteMax_px, 2.0 * truth.stride) << height;
    // A deliberately wrong depth (+1 % distance) is measured as such.
    ReadbackImage frame = renderer.readback();
    for (float& d : frame.depth) d = d / 1.01f;
    ScreenError wrong = measureScreenError(truth, frame, camera);
    EXPECT_GT(wrong.p95_m, 0.005 * height);
  }
}

}  // namespace
}  // namespace globe
