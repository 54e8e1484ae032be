// The analytic haze's per-frame constants (engine/render/terrain_haze.h).
#include "engine/render/terrain_haze.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

namespace globe::testing {
namespace {

// Earth's defaults (planet/atmosphere/atmosphere_parameters.h) as the GPU block packs them.
gpu::AtmosphereGpu earth() {
  gpu::AtmosphereGpu a{};
  const double bottom = 6360000.0;
  a.radii = {float(bottom), float(bottom + 60000.0), -0.2f, 0.0f};
  a.rayleigh = {5.802e-6f, 13.558e-6f, 33.1e-6f, 8000.0f};
  a.mieScattering = {3.996e-6f, 3.996e-6f, 3.996e-6f, 1200.0f};
  a.mieExtinction = {4.44e-6f, 4.44e-6f, 4.44e-6f, 0.8f};
  a.ozone = {0.650e-6f, 1.881e-6f, 0.085e-6f, 25000.0f};
  a.sun = {1.474f, 1.8504f, 1.91198f, 0.004675f};
  a.misc = {15000.0f, 0.1f, 2.0f, 0.99999f};
  return a;
}

TEST(TerrainHaze, SunTransmittanceStraightUpIsTheColumnsOpticalDepth) {
  const gpu::AtmosphereGpu a = earth();
  const glm::dvec3 t = hazeSunTransmittance(a, a.radii.x, 1.0);
  // Rayleigh 8000 m and Mie 1200 m scale heights (their tails above 60 km are negligible), ozone
  // a tent 15 km either side of its peak: 15 km of optical depth at the peak's absorption.
  for (int c = 0; c < 3; ++c) {
    const double rayleigh = (&a.rayleigh.x)[c] * 8000.0 * (1.0 - std::exp(-60000.0 / 8000.0));
    const double depth = rayleigh + 4.44e-6 * 1200.0 + (&a.ozone.x)[c] * 15000.0;
    EXPECT_NEAR(t[c], std::exp(-depth), 2e-3) << c;
  }
  EXPECT_GT(t.x, t.z);  // blue is scattered most: the sun at noon is yellowish
}

TEST(TerrainHaze, SunBelowTheHorizonGivesNoLight) {
  const gpu::AtmosphereGpu a = earth();
  EXPECT_EQ(hazeSunTransmittance(a, a.radii.x, -0.05), glm::dvec3(0.0));
  const glm::dvec3 low = hazeSunTransmittance(a, a.radii.x, 0.07), high = hazeSunTransmittance(a, a.radii.x, 0.8);
  EXPECT_LT(low.z, high.z);
  EXPECT_LT(low.z / low.x, high.z / high.x);  // redder near the horizon
}

TEST(TerrainHaze, ConstantsCarryTheMediaAndTheSunlightOrNothing) {
  const gpu::AtmosphereGpu a = earth();
  gpu::TerrainFrame frame{};
  const glm::dvec3 camera(0.0, 0.0, 6361000.0), sun(0.0, 0.0, 1.0);
  writeHazeConstants(frame, &a, nullptr, camera, sun);
  EXPECT_FLOAT_EQ(frame.hazeRayleigh.z, 33.1e-6f);
  EXPECT_FLOAT_EQ(frame.hazeRayleigh.w, 1.0f / 8000.0f);
  EXPECT_FLOAT_EQ(frame.hazeMie.w, 1.0f / 1200.0f);
  EXPECT_FLOAT_EQ(frame.hazeMieScattering.w, 0.8f);
  EXPECT_FLOAT_EQ(frame.hazeSun.w, a.radii.y);
  const glm::dvec3 t = hazeSunTransmittance(a, a.radii.x, 1.0);
  EXPECT_NEAR(frame.hazeSun.x, 2.0 * 1.474 * t.x, 1e-5);
  writeHazeConstants(frame, nullptr, nullptr, camera, sun);
  EXPECT_EQ(frame.hazeRayleigh.x, 0.0f);
  EXPECT_EQ(frame.hazeRayleigh.w, 0.0f);
  EXPECT_EQ(frame.hazeSun.x, 0.0f);
  EXPECT_EQ(frame.hazeGround.w, 0.0f);  // the white sun and ambient light without air
}

TEST(TerrainHaze, GroundIsLitByTheSkysIrradianceBelowTheCamera) {
  const gpu::AtmosphereGpu a = earth();
  std::vector<float> table(4 * GLOBE_IRRADIANCE_W * GLOBE_IRRADIANCE_H, 0.0f);
  for (int i = 0; i < GLOBE_IRRADIANCE_W; ++i)
    for (int c = 0; c < 3; ++c) table[size_t(4 * i + c)] = float(i * (c + 1));
  gpu::TerrainFrame frame{};
  const glm::dvec3 camera(0.0, 0.0, 6361000.0), sun(1.0, 0.0, 1.0);  // the sun 45 degrees up
  writeHazeConstants(frame, &a, table.data(), camera, sun);
  const glm::dvec3 sky = hazeSkyIrradiance(table.data(), std::sqrt(0.5));
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR((&frame.hazeGround.x)[c], 2.0 * sky[c] / 3.14159265358979, 1e-4 * sky[c]) << c;  // exposure 2
  EXPECT_EQ(frame.hazeGround.w, 1.0f);
}

TEST(TerrainHaze, AtmosphereSeesTheCameraAtItsHeightAboveTheEllipsoid) {
  const glm::dvec3 camera(1.0e6, 2.0e6, 6.0e6);
  EXPECT_EQ(atmosphereCamera(Ellipsoid::sphere(6371000.0), 6371000.0, camera), camera);  // bit for bit
  // WGS84 at 45 N, 3 km up: the geocentric radius is ~10.7 km short of the equatorial one.
  const Ellipsoid wgs84 = Ellipsoid::wgs84();
  const double a = wgs84.equatorialRadius_m();
  glm::dvec3 enu[3];
  const glm::dvec3 at = wgs84.pointAbove(45.0, 20.0, a, 3000.0, &enu);
  EXPECT_LT(glm::length(at), a - 7000.0);
  const glm::dvec3 air = atmosphereCamera(wgs84, a, at);
  EXPECT_NEAR(glm::length(air), a + 3000.0, 1e-6);
  EXPECT_NEAR(glm::dot(glm::normalize(air), enu[2]), 1.0, 1e-12);  // along the geodetic vertical
}

TEST(TerrainHaze, SeaReflectsTheHazesSkyWithAirAndTheFixedColoursWithout) {
  const gpu::AtmosphereGpu a = earth();
  gpu::TerrainFrame frame{};
  frame.skyZenith = frame.skyHorizon = {0.5f, 0.5f, 0.5f, 0.0f};
  const glm::dvec3 camera(0.0, 0.0, 6361000.0), sun(0.0, 0.0, 1.0);
  writeHazeConstants(frame, nullptr, nullptr, camera, sun);
  EXPECT_EQ(frame.skyZenith.x, 0.5f);                   // no air: the renderer's colours stay
  writeHazeConstants(frame, &a, nullptr, camera, sun);  // the sun overhead, single scattering only
  std::printf("[ info ] zenith %.4f %.4f %.4f, horizon %.4f %.4f %.4f\n", frame.skyZenith.x, frame.skyZenith.y,
              frame.skyZenith.z, frame.skyHorizon.x, frame.skyHorizon.y, frame.skyHorizon.z);
  EXPECT_GT(frame.skyZenith.z, 1.5f * frame.skyZenith.x);  // Rayleigh: blue overhead (0.068, 0.098, 0.130)
  EXPECT_GT(frame.skyHorizon.x, frame.skyZenith.x);        // the longer path: paler at the horizon
  EXPECT_LT(frame.skyHorizon.z, frame.hazeSun.z);
}

TEST(TerrainHaze, RayleighScattersTheWhiterSunlightOfItsOwnHeights) {
  const gpu::AtmosphereGpu a = earth();
  gpu::TerrainFrame frame{};
  const glm::dvec3 sun(std::sqrt(1.0 - 0.1 * 0.1), 0.0, 0.1);  // about 6 degrees up
  writeHazeConstants(frame, &a, nullptr, glm::dvec3(0.0, 0.0, 6360000.0 + 20000.0), sun);
  // The column's mean height under a camera 20 km up: 8000 - 20000 e^-2.5 / (1 - e^-2.5) = 6211.5 m.
  const glm::dvec3 aloft = 2.0 * glm::dvec3(1.474, 1.8504, 1.91198) * hazeSunTransmittance(a, 6360000.0 + 6211.49, 0.1);
  EXPECT_NEAR(frame.hazeSunAloft.z, aloft.z, 1e-4 * aloft.z);
  EXPECT_GT(frame.hazeSunAloft.z, 1.5f * frame.hazeSun.z);  // the low sun reddens the ground's light most
  EXPECT_GT(frame.hazeSunAloft.z / frame.hazeSunAloft.x, frame.hazeSun.z / frame.hazeSun.x);
  // From 2 m the column is the ground's: the same light.
  writeHazeConstants(frame, &a, nullptr, glm::dvec3(0.0, 0.0, 6360002.0), sun);
  EXPECT_NEAR(frame.hazeSunAloft.z, frame.hazeSun.z, 1e-3 * frame.hazeSun.z);
}

TEST(TerrainHaze, SkyIrradianceIsReadAlongTheTablesBottomRow) {
  // Texel i of row 0 holds i in every channel; rows above hold garbage that must not be read.
  std::vector<float> table(4 * GLOBE_IRRADIANCE_W * GLOBE_IRRADIANCE_H, -1.0f);
  for (int i = 0; i < GLOBE_IRRADIANCE_W; ++i)
    for (int c = 0; c < 4; ++c) table[size_t(4 * i + c)] = float(i);
  const double last = GLOBE_IRRADIANCE_W - 1;
  EXPECT_NEAR(hazeSkyIrradiance(table.data(), -1.0).x, 0.0, 1e-9);
  EXPECT_NEAR(hazeSkyIrradiance(table.data(), 1.0).y, last, 1e-9);
  EXPECT_NEAR(hazeSkyIrradiance(table.data(), 0.0).z, 0.5 * last, 1e-9);
  EXPECT_NEAR(hazeSkyIrradiance(table.data(), 2.0).x, last, 1e-9);  // clamped
}

}  // namespace
}  // namespace globe::testing
