#include "planet/camera/camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace globe {
namespace {

TEST(Pose, ParsesThreeAndSixFields) {
  auto a = parsePose("45.5,-120,1000", "--at");
  ASSERT_TRUE(a.ok()) << a.error().format();
  EXPECT_EQ(a->latitude_deg, 45.5);
  EXPECT_EQ(a->longitude_deg, -120);
  EXPECT_EQ(a->height_m, 1000);
  EXPECT_TRUE(std::isnan(a->pitch_deg));  // look at the horizon
  auto b = parsePose("0,0,2,90,-30,5", "--at");
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(b->heading_deg, 90);
  EXPECT_EQ(b->pitch_deg, -30);
  EXPECT_EQ(b->roll_deg, 5);
}

TEST(Pose, RejectsBadInputWithOneLine) {
  struct Case {
    const char* text;
    const char* message;
  } cases[] = {
      {"", "--at: expected LAT,LON,HEIGHT[,HEADING,PITCH,ROLL], got ''"},
      {"1,2", "--at: expected LAT,LON,HEIGHT[,HEADING,PITCH,ROLL], got '1,2'"},
      {"1,2,3,4", "--at: expected LAT,LON,HEIGHT[,HEADING,PITCH,ROLL], got '1,2,3,4'"},
      {"abc,2,3", "--at: latitude 'abc' is not a number"},
      {"91,0,3", "--at: latitude must be within [-90, 90] degrees"},
      {"nan,0,3", "--at: latitude must be finite"},
      {"0,inf,3", "--at: longitude must be finite"},
      {"0,0,0", "--at: height must be within (0, 1e12] metres above the surface"},
      {"0,0,-5", "--at: height must be within (0, 1e12] metres above the surface"},
      {"0,0,10,0,-91,0", "--at: pitch must be within [-90, 90] degrees"},
      {"0,0,10,0,0,", "--at: roll '' is not a number"},
  };
  for (const auto& c : cases) {
    auto r = parsePose(c.text, "--at");
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().format(), c.message) << c.text;
  }
}

TEST(Camera, PlacementAndFrameOnTheSphere) {
  const double R = 6371000.0;
  GeodeticPose pose{0, 0, 100, 0, 0, 0};
  Camera cam = cameraFromPose(pose, R, R, 1.0);
  EXPECT_NEAR(cam.position_m.x, R + 100, 1e-6);
  EXPECT_NEAR(cam.position_m.y, 0, 1e-6);
  EXPECT_NEAR(cam.position_m.z, 0, 1e-6);
  // Heading 0 looks north (+z), right is east (+y), up is out (+x).
  EXPECT_NEAR(cam.forward.z, 1, 1e-12);
  EXPECT_NEAR(cam.right.y, 1, 1e-12);
  EXPECT_NEAR(cam.up.x, 1, 1e-12);

  // Heading 90 looks east; pitch -90 looks down.
  Camera east = cameraFromPose({0, 0, 100, 90, 0, 0}, R, R, 1.0);
  EXPECT_NEAR(east.forward.y, 1, 1e-12);
  Camera down = cameraFromPose({10, 20, 100, 30, -90, 0}, R, R, 1.0);
  glm::dvec3 outward = glm::normalize(down.position_m);
  EXPECT_NEAR(glm::dot(down.forward, outward), -1, 1e-12);

  // Orthonormal right-handed frame for awkward poses: poles, +-180, rolled.
  for (GeodeticPose p : {GeodeticPose{90, 0, 1, 0, 0, 0}, GeodeticPose{-90, 180, 1e9, 45, 10, 30},
                         GeodeticPose{0, -180, 0.001, 270, -45, -90}}) {
    Camera c = cameraFromPose(p, R, R, 1.5);
    EXPECT_NEAR(glm::length(c.forward), 1, 1e-12);
    EXPECT_NEAR(glm::dot(c.forward, c.up), 0, 1e-12);
    EXPECT_NEAR(glm::dot(c.forward, c.right), 0, 1e-12);
    EXPECT_NEAR(glm::dot(glm::cross(c.forward, c.up), c.right), 1, 1e-12);
    EXPECT_NEAR(glm::length(c.position_m), R + p.height_m, (R + p.height_m) * 1e-15 + 1e-9);
  }
}

TEST(Camera, ReversedZInfiniteProjection) {
  Camera cam;
  cam.near_m = 0.5;
  glm::dmat4 p = cam.projection();
  auto depth = [&](double dist) {
    glm::dvec4 c = p * glm::dvec4(0, 0, -dist, 1);
    return c.z / c.w;
  };
  EXPECT_DOUBLE_EQ(depth(0.5), 1.0);
  EXPECT_DOUBLE_EQ(depth(1.0), 0.5);
  EXPECT_GT(depth(1e11), 0.0);
  EXPECT_LT(depth(1e11), 1e-11);
}

TEST(Camera, HorizonPitch) {
  EXPECT_NEAR(horizonPitch_deg(0, 6371000), 0, 1e-9);
  EXPECT_NEAR(horizonPitch_deg(1e12, 6371000), -90, 0.01);
  EXPECT_NEAR(horizonPitch_deg(6371000, 6371000), -60, 1e-9);
}

}  // namespace
}  // namespace globe
