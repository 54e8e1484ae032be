// The land cover's reference model (planet/surface/land_cover.cpp): the climate, the masks and their
// blending; and the CPU sampling of it (planet/model/surface_sample.h) that stats and export use.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include <glm/geometric.hpp>

#include "planet/camera/camera.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"
#include "planet/model/sphere_sampling.h"
#include "planet/model/surface_sample.h"
#include "planet/surface/land_cover.h"

namespace globe {
namespace {

LandCoverClass makeClass(const char* name, glm::vec3 colour) {
  LandCoverClass c;
  c.name = name;
  c.colour = colour;
  return c;
}

// A climate without noise: temperature 20 C on the equator at sea level, -20 C at the poles.
LandCover noiselessCover() {
  LandCover cover;
  cover.climate.equator_temperature_c = 20.0;
  cover.climate.pole_temperature_c = -20.0;
  cover.climate.lapse_rate_c_per_km = 6.5;
  cover.climate.temperature_noise_c = 0.0;
  cover.climate.moisture_base = 0.5;
  cover.climate.moisture_noise = 0.0;
  cover.climate.inland_drying_m = 1000.0;
  return cover;
}

gpu::LandCoverParams pack(const LandCover& cover) {
  std::vector<Error> errors;
  appendLandCoverErrors(cover, errors);
  EXPECT_TRUE(errors.empty()) << errors.front().format();
  return packLandCover(cover, 6371000.0, 7, 0.0);
}

LandCoverSite siteAt(double lat_deg, double elevation_m, double slope_deg = 0.0, double first_layer_m = 0.0) {
  LandCoverSite site;
  site.unit_direction = directionFromLatLon(lat_deg, 10.0);
  site.elevation_m = elevation_m;
  site.first_layer_m = first_layer_m;
  site.cos_slope = std::cos(slope_deg * std::numbers::pi / 180.0);
  return site;
}

int sum(const LandCoverMasks& m) { return std::accumulate(m.begin(), m.end(), 0); }

TEST(LandCoverModel, MasksSumTo255AtRandomSites) {
  LandCover cover;  // the default climate, with noise
  const char* names[] = {"a", "b", "c", "d", "e", "f", "g", "h"};
  for (int i = 0; i < kMaxLandCoverClasses; ++i) {
    LandCoverClass c = makeClass(names[i], glm::vec3(0.1f * static_cast<float>(i)));
    c.temperature_min_c = -30.0 + 8.0 * i;  // overlapping bands
    c.temperature_max_c = c.temperature_min_c + 14.0;
    if (i % 2 == 1) c.slope_min_deg = 20.0;
    cover.classes.push_back(c);
  }
  const gpu::LandCoverParams params = pack(cover);
  std::mt19937_64 rng(42);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    LandCoverSite site;
    site.unit_direction = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
    site.elevation_m = -8000.0 + 17000.0 * uniform(rng);
    site.first_layer_m = -5000.0 + 10000.0 * uniform(rng);
    site.cos_slope = uniform(rng);
    const LandCoverMasks m = landCoverMasks(params, site);
    ASSERT_EQ(sum(m), 255) << i;
    const glm::vec3 albedo = landCoverAlbedo(params, m);
    ASSERT_GE(albedo.x, 0.0f);
    ASSERT_LE(albedo.x, 0.7f + 1e-5f);
  }
}

TEST(LandCoverModel, TemperatureFallsWithLatitudeAndHeight) {
  LandCover cover = noiselessCover();
  cover.classes.push_back(makeClass("a", glm::vec3(0.5f)));
  const gpu::LandCoverParams params = pack(cover);
  EXPECT_FLOAT_EQ(climateAt(params, siteAt(0.0, 0.0)).temperature_c, 20.0f);
  EXPECT_NEAR(climateAt(params, siteAt(90.0, 0.0)).temperature_c, -20.0f, 1e-4f);
  // 20 + (-40) sin^2(lat): the square of the direction's z.
  const double s = std::sin(30.0 * std::numbers::pi / 180.0);
  EXPECT_NEAR(climateAt(params, siteAt(30.0, 0.0)).temperature_c, 20.0 - 40.0 * s * s, 1e-4);
  float previous = 100.0f;
  for (double lat = 0.0; lat <= 90.0; lat += 5.0) {
    const float t = climateAt(params, siteAt(lat, 0.0)).temperature_c;
    EXPECT_LT(t, previous) << lat;
    previous = t;
  }
  // The lapse rate above sea level only: 6.5 C per km.
  EXPECT_NEAR(climateAt(params, siteAt(0.0, 2000.0)).temperature_c, 20.0f - 13.0f, 1e-4f);
  EXPECT_NEAR(climateAt(params, siteAt(45.0, 1000.0)).temperature_c,
              climateAt(params, siteAt(45.0, 0.0)).temperature_c - 6.5f, 1e-4f);
  EXPECT_FLOAT_EQ(climateAt(params, siteAt(0.0, -3000.0)).temperature_c, 20.0f);
  // Moisture dries inland: 1 per inland_drying_m the first layer stands above sea level.
  EXPECT_FLOAT_EQ(climateAt(params, siteAt(0.0, 0.0, 0.0, -500.0)).moisture, 0.5f);
  EXPECT_FLOAT_EQ(climateAt(params, siteAt(0.0, 0.0, 0.0, 200.0)).moisture, 0.3f);
  EXPECT_FLOAT_EQ(climateAt(params, siteAt(0.0, 0.0, 0.0, 5000.0)).moisture, 0.0f);  // clamped
}

TEST(LandCoverModel, ASiteWithinOneClassOnlyIsThatClass) {
  LandCover cover = noiselessCover();
  LandCoverClass cold = makeClass("cold", glm::vec3(0.9f));
  cold.temperature_max_c = -5.0;
  LandCoverClass warm = makeClass("warm", glm::vec3(0.1f, 0.3f, 0.1f));
  warm.temperature_min_c = 5.0;
  warm.moisture_min = 0.2;
  warm.moisture_max = 0.8;
  LandCoverClass steep = makeClass("steep", glm::vec3(0.3f));
  steep.slope_min_deg = 40.0;
  cover.classes = {cold, warm, steep};
  const gpu::LandCoverParams params = pack(cover);
  const LandCoverMasks equator = landCoverMasks(params, siteAt(0.0, 100.0));  // 19.35 C, moisture 0.5
  EXPECT_EQ(equator[1], 255);
  EXPECT_EQ(equator[0] + equator[2], 0);
  EXPECT_EQ(landCoverMasks(params, siteAt(80.0, 0.0))[0], 255);                           // -18.8 C
  const LandCoverMasks cold_and_steep = landCoverMasks(params, siteAt(80.0, 0.0, 60.0));  // both rules hold
  EXPECT_EQ(std::abs(cold_and_steep[0] - cold_and_steep[2]), 1);
  EXPECT_EQ(cold_and_steep[1], 0);
  EXPECT_EQ(landCoverAlbedo(params, equator), glm::vec3(0.1f, 0.3f, 0.1f));
}

TEST(LandCoverModel, TheFirstClassTakesOverWhereNoRuleHolds) {
  LandCover cover = noiselessCover();
  LandCoverClass hot = makeClass("hot", glm::vec3(0.8f, 0.6f, 0.3f));
  hot.temperature_min_c = 40.0;
  LandCoverClass frozen = makeClass("frozen", glm::vec3(0.9f));
  frozen.temperature_max_c = -40.0;
  cover.classes = {hot, frozen};
  const gpu::LandCoverParams params = pack(cover);
  const LandCoverMasks m = landCoverMasks(params, siteAt(10.0, 50.0));
  EXPECT_EQ(m[0], 255);
  EXPECT_EQ(m[1], 0);
  // And the other way round: the first class's weight is kept where it holds.
  cover.classes = {frozen, hot};
  EXPECT_EQ(landCoverMasks(pack(cover), siteAt(10.0, 50.0))[0], 255);
}

TEST(LandCoverModel, BlendingAcrossAnEdgeIsMonotone) {
  LandCover cover = noiselessCover();
  cover.climate.elevation_blend_m = 40.0;
  LandCoverClass beach = makeClass("beach", glm::vec3(0.6f, 0.55f, 0.4f));
  beach.elevation_max_m = 15.0;
  LandCoverClass grass = makeClass("grass", glm::vec3(0.1f, 0.3f, 0.05f));
  grass.elevation_min_m = 15.0;
  cover.classes = {beach, grass};
  const gpu::LandCoverParams params = pack(cover);
  int previous_beach = 256;
  bool saw_blend = false;
  for (double h = -20.0; h <= 50.0; h += 0.5) {
    const LandCoverMasks m = landCoverMasks(params, siteAt(0.0, h));
    ASSERT_EQ(m[0] + m[1], 255);
    EXPECT_LE(m[0], previous_beach) << h;  // beach fades out, grass in, never back
    saw_blend = saw_blend || (m[0] > 10 && m[0] < 245);
    previous_beach = m[0];
  }
  EXPECT_TRUE(saw_blend);
  EXPECT_EQ(landCoverMasks(params, siteAt(0.0, -10.0))[0], 255);
  EXPECT_EQ(landCoverMasks(params, siteAt(0.0, 40.0))[1], 255);
  const LandCoverMasks edge = landCoverMasks(params, siteAt(0.0, 15.0));  // half and half on the edge
  EXPECT_EQ(std::abs(edge[0] - edge[1]), 1);
  // The same across a temperature edge, walking polewards.
  cover.classes[0].elevation_max_m = kUnboundedRange;
  cover.classes[0].temperature_min_c = 0.0;
  cover.classes[1].elevation_min_m = -kUnboundedRange;
  cover.classes[1].temperature_max_c = 0.0;
  const gpu::LandCoverParams by_temperature = pack(cover);
  int previous_cold = -1;
  for (double lat = 0.0; lat <= 90.0; lat += 1.0) {
    const int cold = landCoverMasks(by_temperature, siteAt(lat, 0.0))[1];
    EXPECT_GE(cold, previous_cold) << lat;
    previous_cold = cold;
  }
  EXPECT_EQ(previous_cold, 255);
}

TEST(LandCoverModel, PackedValues) {
  LandCover cover = noiselessCover();
  cover.climate.noise_wavelength_m = 1.0e6;
  cover.classes.push_back(makeClass("a", glm::vec3(0.25f, 0.5f, 0.75f)));
  const gpu::LandCoverParams p = packLandCover(cover, 6371000.0, 7, -12.0);
  EXPECT_EQ(p.class_count, 1U);
  EXPECT_FLOAT_EQ(p.noise_scale, 6.371f);
  EXPECT_FLOAT_EQ(p.lapse_rate_c_per_m, 0.0065f);
  EXPECT_FLOAT_EQ(p.inland_drying_per_m, 0.001f);
  EXPECT_EQ(p.sea_level_m, -12.0f);
  EXPECT_EQ(p.classes[0].r, 0.25f);
  EXPECT_EQ(p.classes[0].temperature_max_c, 1e30f);
  EXPECT_EQ(p.classes[0].slope_max_deg, 90.0f);
  EXPECT_EQ(p.classes[1].r, 0.0f);  // unused slots are zero
}

// ---- sampling the model on a planet (stats, export) ----

PlanetDescription planetWithCover(double amplitude_m, bool water) {
  PlanetDescription p;
  p.radius_m = 6371000.0;
  p.seed = 3;
  ElevationLayer layer;
  layer.name = "continents";
  layer.octaves = 4;
  layer.wavelength_m = 3.0e6;
  layer.amplitude_m = amplitude_m;
  p.layers = {layer};
  p.water.enabled = water;
  p.land_cover = noiselessCover();
  LandCoverClass low = makeClass("low", glm::vec3(0.6f, 0.5f, 0.3f));
  low.elevation_max_m = 500.0;
  LandCoverClass high = makeClass("high", glm::vec3(0.3f));
  high.elevation_min_m = 500.0;
  p.land_cover.classes = {low, high};
  EXPECT_TRUE(validatePlanet(p).ok());
  return p;
}

TEST(SurfaceSample, FlatGroundHasNoSlope) {
  const ElevationModel flat(planetWithCover(0.0, false));
  for (double lat : {0.0, 45.0, 89.9, -60.0}) {
    const glm::dvec3 d = directionFromLatLon(lat, 33.0);
    EXPECT_NEAR(groundCosSlope(flat, d, 30.0), 1.0, 1e-9) << lat;
    const LandCoverSite site = landCoverSiteAt(flat, d, 30.0);
    EXPECT_EQ(site.elevation_m, 0.0);
    EXPECT_EQ(site.first_layer_m, 0.0);
    EXPECT_EQ(site.unit_direction, d);
  }
}

// The slope agrees with one from latitude/longitude differences of the elevation (a sphere).
TEST(SurfaceSample, SlopeFromTheElevationGradient) {
  const ElevationModel model(planetWithCover(4000.0, false));
  const double spacing = 200.0;
  const double step_deg = spacing / model.radius_m() * 180.0 / std::numbers::pi;
  for (double lat : {-50.0, -10.0, 5.0, 37.0, 61.0}) {
    for (double lon : {-120.0, 0.5, 80.0}) {
      auto h = [&](double dlat, double dlon) {
        return model.elevation_m(
            directionFromLatLon(lat + dlat, lon + dlon / std::cos(lat * std::numbers::pi / 180.0)));
      };
      const double gx = (h(0, step_deg) - h(0, -step_deg)) / (2.0 * spacing);
      const double gy = (h(step_deg, 0) - h(-step_deg, 0)) / (2.0 * spacing);
      const double expected = 1.0 / std::sqrt(1.0 + gx * gx + gy * gy);
      EXPECT_NEAR(groundCosSlope(model, directionFromLatLon(lat, lon), spacing), expected, 2e-4) << lat << "," << lon;
    }
  }
}

TEST(SurfaceSample, TheSeaIsDrawnAtSeaLevel) {
  PlanetDescription p = planetWithCover(4000.0, true);
  p.sea_level_m = 100.0;
  const ElevationModel model(p);
  for (double lat = -80.0; lat <= 80.0; lat += 7.0) {
    const glm::dvec3 d = directionFromLatLon(lat, 2.0 * lat);
    const double ground = model.elevation_m(d);
    const LandCoverSite site = landCoverSiteAt(model, d, 30.0);
    EXPECT_EQ(site.elevation_m, std::max(ground, 100.0));
    EXPECT_EQ(site.first_layer_m, model.firstLayer_m(d));
  }
}

TEST(SurfaceSample, SharesCoverThePlanetWhateverTheThreads) {
  const ElevationModel model(planetWithCover(4000.0, true));
  const LandCoverShares one = computeLandCoverShares(model, 20000, 1);
  const LandCoverShares two = computeLandCoverShares(model, 20000, 2);
  ASSERT_EQ(one.class_fraction.size(), 2U);
  EXPECT_EQ(one.class_fraction, two.class_fraction);
  EXPECT_EQ(one.sea_fraction, two.sea_fraction);
  EXPECT_NEAR(one.sea_fraction + one.class_fraction[0] + one.class_fraction[1], 1.0, 1e-12);
  EXPECT_GT(one.sea_fraction, 0.2);
  EXPECT_LT(one.sea_fraction, 0.8);
  EXPECT_GT(one.class_fraction[0], 0.01);
  EXPECT_GT(one.class_fraction[1], 0.01);
  // Without water the same ground is all land.
  const LandCoverShares dry = computeLandCoverShares(ElevationModel(planetWithCover(4000.0, false)), 20000, 2);
  EXPECT_EQ(dry.sea_fraction, 0.0);
  EXPECT_NEAR(dry.class_fraction[0] + dry.class_fraction[1], 1.0, 1e-12);
}

TEST(SurfaceSample, MapPixelsAreTheAlbedoOrTheSea) {
  const ElevationModel model(planetWithCover(4000.0, true));
  const gpu::LandCoverParams& params = model.landCover();
  const std::uint32_t w = 64, h = 32;
  std::vector<glm::vec3> map(static_cast<std::size_t>(w) * h);
  landCoverEquirectRows(model, w, h, 0, map, 2);
  int sea = 0;
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) {
      const glm::dvec3 d = equirectPixelDirection(x, y, w, h);
      const double ground = model.elevation_m(d);
      const glm::vec3 expected = ground < 0.0
                                     ? seaColour(model.water(), -ground)
                                     : landCoverAlbedo(params, landCoverMasks(params, landCoverSiteAt(model, d, 30.0)));
      sea += ground < 0.0 ? 1 : 0;
      ASSERT_EQ(map[static_cast<std::size_t>(y) * w + x], expected) << x << "," << y;
    }
  }
  EXPECT_GT(sea, 100);
  EXPECT_LT(sea, 64 * 32 - 100);
}

// The presets' land cover: every class covers some of the planet, and earthlike's is varied.
TEST(LandCoverPresets, EveryClassHasItsShare) {
  for (const char* name : {"earthlike", "marslike", "moonlike", "asteroid", "gasgiant-core"}) {
    SCOPED_TRACE(name);
    const auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/" + name + ".toml");
    ASSERT_TRUE(planet.ok()) << planet.error().format();
    ASSERT_TRUE(planet->land_cover.enabled());
    const LandCoverShares shares = computeLandCoverShares(ElevationModel(*planet), 50000, 2);
    int above_2_percent = 0;
    for (std::size_t i = 0; i < shares.class_fraction.size(); ++i) {
      EXPECT_GT(shares.class_fraction[i], 0.001) << planet->land_cover.classes[i].name;
      above_2_percent += shares.class_fraction[i] >= 0.02 ? 1 : 0;
    }
    if (std::string(name) == "earthlike") {
      EXPECT_GE(above_2_percent, 5);
      EXPECT_NEAR(shares.sea_fraction, 0.66, 0.02);
    }
  }
  // Earthlike's ice: on the polar land at sea level, not on the equator's.
  const auto earth = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
  ASSERT_TRUE(earth.ok());
  const ElevationModel model(*earth);
  const gpu::LandCoverParams& params = model.landCover();
  const std::size_t snow = earth->land_cover.classes.size() - 1;
  ASSERT_EQ(earth->land_cover.classes[snow].name, "snow");
  EXPECT_EQ(landCoverMasks(params, siteAt(88.0, 100.0, 0.0, 100.0))[snow], 255);
  EXPECT_EQ(landCoverMasks(params, siteAt(5.0, 100.0, 0.0, 100.0))[snow], 0);
  EXPECT_EQ(landCoverMasks(params, siteAt(5.0, 2000.0, 0.0, 100.0))[snow], 0);
}

}  // namespace
}  // namespace globe
