// Sampling over the sphere (globe planet stats/export): Fibonacci directions are unit and uniform,
// equirectangular pixel centres follow the documented convention, and the statistics do not depend
// on the number of threads.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "planet/model/planet_file.h"
#include "planet/model/sphere_sampling.h"

namespace globe {
namespace {

TEST(SphereSampling, FibonacciDirectionsAreUnitAndUniform) {
  constexpr std::uint64_t n = 100000;
  glm::dvec3 sum(0.0);
  std::uint64_t north = 0;
  std::uint64_t band = 0;  // |z| < 0.5: 50 % of the area of a sphere
  for (std::uint64_t i = 0; i < n; ++i) {
    const glm::dvec3 d = fibonacciDirection(i, n);
    ASSERT_NEAR(glm::length(d), 1.0, 1e-15);
    sum += d;
    north += d.z > 0.0 ? 1U : 0U;
    band += std::abs(d.z) < 0.5 ? 1U : 0U;
  }
  EXPECT_LT(glm::length(sum) / n, 1e-4);
  EXPECT_EQ(north, n / 2);
  EXPECT_NEAR(static_cast<double>(band) / n, 0.5, 1e-4);
}

TEST(SphereSampling, EquirectCornersAndSeam) {
  // Top-left pixel of a 360 x 180 map: latitude 89.5, longitude -179.5; the last column +179.5.
  const glm::dvec3 a = equirectPixelDirection(0, 0, 360, 180);
  const glm::dvec3 b = equirectPixelDirection(359, 0, 360, 180);
  EXPECT_NEAR(std::asin(a.z) * 180.0 / std::numbers::pi, 89.5, 1e-12);
  EXPECT_NEAR(std::atan2(a.y, a.x) * 180.0 / std::numbers::pi, -179.5, 1e-12);
  EXPECT_NEAR(std::atan2(b.y, b.x) * 180.0 / std::numbers::pi, 179.5, 1e-12);
  const glm::dvec3 c = equirectPixelDirection(180, 179, 360, 180);
  EXPECT_NEAR(std::asin(c.z) * 180.0 / std::numbers::pi, -89.5, 1e-12);
}

TEST(SphereSampling, ParallelForCoversEveryItemOnce) {
  std::vector<std::atomic<int>> hits(10007);
  double last = 0.0;
  parallelFor(
      hits.size(), 100, 3,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) hits[i].fetch_add(1);
      },
      [&](double f) {
        EXPECT_GE(f, last);
        last = f;
      });
  EXPECT_EQ(last, 1.0);
  for (const auto& h : hits) ASSERT_EQ(h.load(), 1);
}

TEST(SphereSampling, ParallelForRethrowsTheBodysException) {
  // A body that throws on a helper thread must not terminate the process.
  EXPECT_THROW(parallelFor(1000, 10, 3,
                           [](std::size_t begin, std::size_t) {
                             if (begin == 500) throw std::runtime_error("chunk 50");
                           }),
               std::runtime_error);
}

TEST(SphereSampling, StatsDoNotDependOnThreads) {
  const Result<PlanetDescription> planet =
      loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
  ASSERT_TRUE(planet.ok());
  const ElevationModel model(*planet);
  const ElevationStats one = computeElevationStats(model, 20000, 10, 1);
  const ElevationStats two = computeElevationStats(model, 20000, 10, 2);
  EXPECT_EQ(one.min_m, two.min_m);
  EXPECT_EQ(one.max_m, two.max_m);
  EXPECT_EQ(one.mean_m, two.mean_m);
  EXPECT_EQ(one.histogram, two.histogram);
  EXPECT_EQ(one.median_m, two.median_m);
  double total = 0.0;
  for (double f : one.histogram) total += f;
  EXPECT_NEAR(total, 1.0, 1e-9);
  EXPECT_LE(one.min_m, one.p01_m);
  EXPECT_LE(one.p99_m, one.max_m);
  const ElevationRange bounds = model.bounds();
  EXPECT_GE(one.min_m, bounds.min_m);
  EXPECT_LE(one.max_m, bounds.max_m);
  // earthlike: roughly two thirds below sea level (docs/elevation.md: 34 % above).
  EXPECT_NEAR(one.below_sea_fraction, 0.66, 0.03);
}

}  // namespace
}  // namespace globe
