// The crater layer kind: profile shape, the 2x2x2 window holding every crater, continuity, bounds,
// the size–frequency distribution and the planet file key.
#include "planet/elevation/crater_field.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <random>

namespace globe::testing {
namespace {

TEST(CraterProfile, BowlRimAndEjectaMeetContinuously) {
  EXPECT_EQ(craterProfile(0.0), -1.0);
  EXPECT_NEAR(craterProfile(std::nextafter(1.0, 0.0)), kCraterRimHeight, 1e-12);
  EXPECT_EQ(craterProfile(1.0), kCraterRimHeight);
  EXPECT_NEAR(craterProfile(std::nextafter(1.5, 0.0)), 0.0, 1e-12);
  EXPECT_EQ(craterProfile(1.5), 0.0);
  EXPECT_EQ(craterProfile(9.0), 0.0);
  // The floor is the lowest point, the rim crest the highest.
  for (double s = 0.0; s < 2.0; s += 1.0 / 64.0) {
    EXPECT_GE(craterProfile(s), -1.0);
    EXPECT_LE(craterProfile(s), kCraterRimHeight);
  }
}

// Every crater that can reach q: the 4x4x4 cells around it, combined without the window's shortcut.
double craterFieldBruteForce(double x, double y, double z, std::uint32_t seed) {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  double deepest = 0.0, raised = 0.0;
  for (int dz = -2; dz <= 1; ++dz)
    for (int dy = -2; dy <= 1; ++dy)
      for (int dx = -2; dx <= 1; ++dx) {
        const auto ix = static_cast<std::int64_t>(fx) + dx, iy = static_cast<std::int64_t>(fy) + dy,
                   iz = static_cast<std::int64_t>(fz) + dz;
        const double c = craterCell(latticePointHash(ix, iy, iz, seed), x - double(ix), y - double(iy), z - double(iz));
        deepest = std::min(deepest, c);
        raised += std::max(c, 0.0);
      }
  return deepest + raised;
}

TEST(CraterField, TheWindowHoldsEveryCraterThatReachesAPoint) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  int nonzero = 0;
  for (int i = 0; i < 20000; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    const double field = craterField(x, y, z, 1234U);
    ASSERT_NEAR(field, craterFieldBruteForce(x, y, z, 1234U), 1e-12) << x << " " << y << " " << z;
    EXPECT_GE(field, kCraterFieldMin);
    EXPECT_LE(field, kCraterFieldMax);
    nonzero += field != 0.0;
  }
  // A few per cent of space lies within some crater's reach.
  EXPECT_GT(nonzero, 20000 / 50);
  EXPECT_LT(nonzero, 20000 / 2);
}

TEST(CraterField, IsContinuousWithinItsSlopeBound) {
  const double step = 1.0 / 4096.0;  // cells
  double previous = craterField(0.1, 0.2, 0.3, 5U);
  double steepest = 0.0;
  for (int i = 1; i < 200000; ++i) {
    const double t = i * step;
    const double f = craterField(0.1 + t, 0.2 + 0.37 * t, 0.3 - 0.21 * t, 5U);
    steepest = std::max(steepest, std::abs(f - previous) / (step * std::sqrt(1.0 + 0.37 * 0.37 + 0.21 * 0.21)));
    previous = f;
  }
  EXPECT_GT(steepest, 1.0);  // the line crosses craters
  EXPECT_LE(steepest, kCraterFieldSlopeBound);
}

// Half the cells hold a crater and the four radius classes are equally likely, so per octave the
// craters per unit volume are 1/2 per cell^3: each octave (cells 1/lacunarity as large) has
// lacunarity^2 times more craters per unit of surface, N(>D) ∝ D^-2.
TEST(CraterField, CellsHoldHalfACraterWithUniformRadiusClasses) {
  std::map<std::uint32_t, int> classes;
  int occupied = 0, cells = 0;
  for (std::int64_t x = -40; x < 40; ++x)
    for (std::int64_t y = -40; y < 40; ++y, ++cells) {
      const std::uint32_t h = hashMix32(latticePointHash(x, y, 3, 99U));
      if (h & 1U) {
        ++occupied;
        ++classes[(h >> 1) & 3U];
      }
    }
  EXPECT_NEAR(double(occupied) / cells, 0.5, 0.03);
  for (std::uint32_t k = 0; k < 4; ++k) EXPECT_NEAR(double(classes[k]) / occupied, 0.25, 0.03) << k;
}

TEST(CraterLayer, PlanetFileTakesTheKindAndBoundsHoldOnTheMoon) {
  auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/moonlike.toml");
  ASSERT_TRUE(planet.ok()) << planet.error().format();
  int craterLayers = 0;
  for (const ElevationLayer& l : planet->layers) craterLayers += l.kind == LayerKind::kCraters;
  EXPECT_GE(craterLayers, 1);
  const ElevationModel model(*planet);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int i = 0; i < 5000; ++i) {
    const double h = model.elevation_m(glm::normalize(glm::dvec3(n(rng), n(rng), n(rng))));
    EXPECT_GE(h, model.bounds().min_m);
    EXPECT_LE(h, model.bounds().max_m);
  }
  EXPECT_EQ(layerKindName(LayerKind::kCraters), "craters");
}

}  // namespace
}  // namespace globe::testing
