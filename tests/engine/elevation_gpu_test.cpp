// The compute shader's double elevation must match the CPU reference (<= 1e-6 m).
#include "engine/generation/elevation_sampler.h"
#include "planet/camera/camera.h"
#include "planet/model/planet_file.h"
#include "tests/support/gpu_test.h"

#include <cmath>
#include <random>

namespace globe::testing {
namespace {

class ElevationGpuTest : public GpuTest {};

std::vector<glm::dvec3> testDirections() {
  std::vector<glm::dvec3> dirs;
  // Poles, the antimeridian, the equator, signed zeros.
  for (double lat : {-90.0, -89.999999, -45.0, -26.56505117707799, 0.0, 26.56505117707799, 45.0, 89.999999, 90.0})
    for (double lon : {-180.0, -179.9999999, -72.0, -36.0, -0.0, 0.0, 36.0, 72.0, 144.0, 179.9999999, 180.0})
      dirs.push_back(directionFromLatLon(lat, lon));
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int i = 0; i < 4000; ++i) dirs.push_back(glm::normalize(glm::dvec3(n(rng), n(rng), n(rng))));
  // Clusters at sub-millimetre spacing (deep LOD levels).
  glm::dvec3 base = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  for (int i = 0; i < 200; ++i) dirs.push_back(glm::normalize(base + glm::dvec3(i * 1e-11, -i * 7e-12, i * 3e-12)));
  return dirs;
}

TEST_F(ElevationGpuTest, MatchesCpuReferenceOnEveryPreset) {
  for (const char* file : {"earthlike.toml", "moonlike.toml", "asteroid.toml"}) {
    auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/" + file);
    ASSERT_TRUE(planet.ok()) << planet.error().format();
    ElevationModel model(*planet);
    auto dirs = testDirections();
    ElevationSampler sampler(device(), model.params(), uint32_t(dirs.size()));
    auto gpu = sampler.sample(dirs);
    double worst = 0;
    int exact = 0;
    for (size_t i = 0; i < dirs.size(); ++i) {
      double cpu = model.elevation_m(dirs[i]);
      ASSERT_TRUE(std::isfinite(gpu[i])) << i;
      worst = std::max(worst, std::abs(gpu[i] - cpu));
      exact += gpu[i] == cpu;
      EXPECT_LE(std::abs(gpu[i] - cpu), 1e-6) << file << " direction " << i;
    }
    std::printf("[ info ] %s: %zu samples, %d bit-identical, worst |gpu - cpu| = %.3g m\n", file, dirs.size(), exact,
                worst);
  }
}

}  // namespace
}  // namespace globe::testing
