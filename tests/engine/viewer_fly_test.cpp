// The fly camera near the ground (issue 37 item 4): a speed floor a person can fly with, terrain
// following instead of pinning the camera against the ground, and the horizon kept in view when
// descending over the sea.
#include "engine/viewer/fly_camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace globe {
namespace {

constexpr double kR = 6371000.0;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Rolling hills: +-300 m over ~10 km.
double hills(const glm::dvec3& dir) { return kR + 300.0 * std::sin(dir.x * 4000.0) * std::cos(dir.z * 3000.0); }

double pitchOf(const FlyCamera& cam) { return std::asin(glm::dot(cam.forward(), glm::normalize(cam.position_m()))); }

TEST(FlyCameraNearGround, SpeedHasAFloorOfAFewMetresASecond) {
  FlyCamera cam(GeodeticPose{20, 10, 0.01, 0, 0, 0}, kR);
  EXPECT_GE(cam.speed_mps(), 5.0);
  const glm::dvec3 before = cam.position_m();
  FlyControls c;
  c.forward = 1;
  for (int i = 0; i < 60; ++i) cam.update(c, 1.0 / 60.0);
  EXPECT_NEAR(glm::length(cam.position_m() - before), FlyCamera::kMinSpeed_mps, 0.01);
  // Level flight at 1 cm stays at 1 cm: nothing pops it up (the pitch creeps up by the arc flown, 2e-8 rad a step).
  EXPECT_NEAR(cam.altitude_m(), 0.01, 1e-4);
}

TEST(FlyCameraNearGround, FollowsTheTerrainInsteadOfStoppingOnIt) {
  // Diving forward into rolling hills from 1 km: the camera comes down to eye height and then runs
  // on over the hills at that height, at the floor speed, never pinned.
  FlyCamera cam(GeodeticPose{0.5, 0.5, 1000, 90, -30, 0}, kR, hills);
  FlyControls c;
  c.forward = 1;
  for (int i = 0; i < 1200; ++i) cam.update(c, 1.0 / 60.0);
  EXPECT_NEAR(cam.altitude_m(), FlyCamera::kEyeHeight_m, 1e-6);
  glm::dvec3 last = cam.position_m();
  for (int i = 0; i < 600; ++i) {  // 10 s along the ground
    cam.update(c, 1.0 / 60.0);
    EXPECT_NEAR(cam.altitude_m(), FlyCamera::kEyeHeight_m, 1e-6) << i;
    EXPECT_GT(glm::length(cam.position_m() - last), 5.0 / 60.0) << i;  // >= 5 m/s along the ground
    last = cam.position_m();
  }
}

TEST(FlyCameraNearGround, ClimbsBackUpWhenAsked) {
  FlyCamera cam(GeodeticPose{0.5, 0.5, 2, 0, 0, 0}, kR, hills);
  FlyControls c;
  c.up = 1;
  for (int i = 0; i < 120; ++i) cam.update(c, 1.0 / 60.0);
  EXPECT_GT(cam.altitude_m(), 20.0);
}

TEST(FlyCameraNearGround, AMoveIntoASlopeSlidesOverIt) {
  // A guard that stops a move at a 500 m wall north of latitude 1 degree (a cliff face), as the
  // terrain's ray cast would: the rest of the move carries the camera on over the top.
  auto cliff = [](const glm::dvec3& dir) { return kR + (std::asin(dir.z) > 1.0 * kDeg ? 500.0 : 0.0); };
  auto guard = [&](const glm::dvec3& from, const glm::dvec3& to, double clearance_m) {
    const double lat = std::asin(glm::normalize(to).z);
    if (lat <= 1.0 * kDeg || glm::length(to) > kR + 500.0 + clearance_m) return to;
    return from;  // stopped at the face
  };
  FlyCamera cam(GeodeticPose{0.99, 0, 100, 0, 0, 0}, kR, cliff, guard);  // 1.1 km south of it, looking north
  FlyControls c;
  c.forward = 1;
  for (int i = 0; i < 1200; ++i) cam.update(c, 1.0 / 60.0);
  EXPECT_GT(std::asin(glm::normalize(cam.position_m()).z), 1.0 * kDeg);  // past the face
  EXPECT_GT(cam.altitude_m(), 1.0);
}

TEST(FlyCameraNearGround, DescentOverTheSeaKeepsTheHorizonInView) {
  FlyCamera cam(GeodeticPose{0, -30, 20000, 0, -80, 0}, kR);
  cam.setSeaQuery([](const glm::dvec3&) { return true; });
  FlyControls c;
  c.forward = 1;
  c.boost = true;
  for (int i = 0; i < 900; ++i) cam.update(c, 1.0 / 60.0);
  EXPECT_NEAR(cam.altitude_m(), FlyCamera::kEyeHeight_m, 1e-6);
  // The horizon (a hair below level at 2 m) is in the upper half of the 60-degree view.
  const Camera view = cam.camera(16.0 / 9.0);
  EXPECT_GT(pitchOf(cam), -0.25 * view.verticalFov_rad - 0.01);
  EXPECT_LT(pitchOf(cam), 0.0);  // raised no further than needed

  // Over land the same dive keeps the pitch the user chose.
  FlyCamera land(GeodeticPose{0, -30, 20000, 0, -80, 0}, kR);
  for (int i = 0; i < 60; ++i) land.update(c, 1.0 / 60.0);
  EXPECT_LT(pitchOf(land), -79.9 * kDeg);  // only the arc flown (0.03 degrees) turned it
}

TEST(FlyCameraNearGround, MoveToJumpsToAPose) {
  FlyCamera cam(GeodeticPose{20, 10, 2e6, 0, 0, 0}, kR);
  cam.moveTo(GeodeticPose{46.5, 7.9, 1500, 90, -10, 0});
  EXPECT_NEAR(cam.altitude_m(), 1500, 1e-6);
  EXPECT_NEAR(cam.latLon_deg().x, 46.5, 1e-9);
  EXPECT_NEAR(cam.latLon_deg().y, 7.9, 1e-9);
  EXPECT_NEAR(pitchOf(cam), -10 * kDeg, 1e-9);
}

}  // namespace
}  // namespace globe
