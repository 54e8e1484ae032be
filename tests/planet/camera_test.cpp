#include "planet/camera/camera.h"
#include "planet/camera/camera_orientation.h"

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

// `--at LAT,LON,HEIGHT,...` on WGS84 (issue #18): geodetic latitude, the height along the normal above
// a ground at ellipsoidal height g; the camera is GeographicLib's point at g + HEIGHT, and
// poseFromCamera gives the pose back (poles, ±180°, signed zero, 1 cm .. 1e8 m).
TEST(Camera, AtRoundTripsOnWgs84) {
  const Ellipsoid wgs84 = Ellipsoid::wgs84();
  const double a = wgs84.equatorialRadius_m();
  const double kDeg = 3.14159265358979323846 / 180.0;
  int cases = 0;
  for (double lat : {-90.0, -89.999, -45.0, -0.0, 0.0, 22.1, 60.0, 89.999, 90.0})
    for (double lon : {-180.0, -98.4, 0.0, 7.5, 179.999, 180.0})
      for (double ground_m : {-400.0, 0.0, 8000.0})
        for (double height_m : {0.01, 2.0, 1000.0, 1e5, 2e7, 1e8}) {
          SCOPED_TRACE(::testing::Message() << lat << "," << lon << " ground " << ground_m << " height " << height_m);
          const GeodeticPose pose{lat, lon, height_m, 30.0, -20.0, 5.0};
          const Camera c = cameraFromPose(pose, a + ground_m, wgs84, 1.5);
          // The ellipsoidal height of the camera is ground + height, and it stands over the given latitude.
          const GeodeticPoint g = wgs84.geodeticFromGeocentric(c.position_m);
          const double tolerance_m = std::max(1e-6, 4e-16 * glm::length(c.position_m));
          EXPECT_NEAR(g.height_m, ground_m + height_m, tolerance_m);
          EXPECT_NEAR(g.latitude_deg, lat, 1e-9);
          const glm::dvec3 expected = wgs84.geocentricFromGeodetic({lat, lon, (a + ground_m - a) + height_m});
          EXPECT_LE(glm::length(c.position_m - expected), 1e-9 * glm::length(expected));
          // Not where a sphere of radius a would put it (away from the equator and the poles).
          if (std::abs(lat) > 1.0 && std::abs(lat) < 89.0) {
            const glm::dvec3 onSphere = directionFromLatLon(lat, lon) * (a + ground_m + height_m);
            EXPECT_GT(glm::length(c.position_m - onSphere), 1000.0);
          }
          const GeodeticPose back = poseFromCamera(c, a + ground_m, wgs84);
          EXPECT_NEAR(back.latitude_deg, lat, 1e-9);
          EXPECT_NEAR(back.height_m, height_m, tolerance_m);
          if (std::abs(lat) < 89.99) {  // at the poles longitude and heading turn together
            const double dLon = std::remainder(back.longitude_deg - lon, 360.0);
            EXPECT_NEAR(dLon * std::cos(lat * kDeg), 0.0, 1e-9);
            EXPECT_NEAR(std::remainder(back.heading_deg - pose.heading_deg, 360.0), 0.0, 1e-6);
            EXPECT_NEAR(back.roll_deg, pose.roll_deg, 1e-6);
          }
          EXPECT_NEAR(back.pitch_deg, pose.pitch_deg, 1e-6);
          ++cases;
        }
  EXPECT_EQ(cases, 9 * 6 * 3 * 6);
}

// --height-ref ellipsoid: HEIGHT is the ellipsoidal height; the camera stands exactly there, the
// ground below it whatever its elevation (under the ellipsoid too), and under the ground is refused.
TEST(Pose, EllipsoidalHeightsPlaceTheCameraAtThatHeight) {
  EXPECT_EQ(*parseHeightReference("ground", "--height-ref"), HeightReference::ground);
  EXPECT_EQ(*parseHeightReference("ellipsoid", "--height-ref"), HeightReference::sphere);
  EXPECT_EQ(*parseHeightReference("sphere", "--height-ref"), HeightReference::sphere);
  EXPECT_EQ(parseHeightReference("sea", "--height-ref").error().format(),
            "--height-ref: must be 'ground', 'sphere' or 'ellipsoid', got 'sea'");
  EXPECT_EQ(parsePose("0,0,-5", "--at", HeightReference::sphere)->height_m, -5.0);
  EXPECT_EQ(parsePose("0,0,-2e5", "--at", HeightReference::sphere).error().format(),
            "--at: height must be within [-100000, 1e12] metres above the reference surface");
  EXPECT_EQ(parsePose("95,0,10", "--at", HeightReference::sphere).error().format(),
            "--at: latitude must be within [-90, 90] degrees");

  const Ellipsoid wgs84 = Ellipsoid::wgs84();
  const double a = wgs84.equatorialRadius_m();
  for (double lat : {-90.0, -33.0, 0.0, 46.5, 90.0})
    for (double ground_m : {-420.0, 0.0, 4807.0})
      for (double height_m : {-400.0, 1.0, 5000.0, 2e7}) {
        SCOPED_TRACE(::testing::Message() << lat << " ground " << ground_m << " height " << height_m);
        auto pose = parsePose(std::to_string(lat) + ",7.5," + std::to_string(height_m) + ",0,-10,0", "--at",
                              HeightReference::sphere);
        ASSERT_TRUE(pose.ok());
        auto above = poseAboveGround(*pose, a + ground_m, a, "--at");
        if (height_m <= ground_m) {
          ASSERT_FALSE(above.ok());
          EXPECT_NE(above.error().format().find("--at: height"), std::string::npos);
          EXPECT_NE(above.error().format().find("the camera must be above it"), std::string::npos);
          continue;
        }
        ASSERT_TRUE(above.ok()) << above.error().format();
        const Camera c = cameraFromPose(*above, a + ground_m, wgs84, 1.5);
        const GeodeticPoint g = wgs84.geodeticFromGeocentric(c.position_m);
        EXPECT_NEAR(g.height_m, height_m, std::max(1e-6, 4e-16 * glm::length(c.position_m)));
        EXPECT_NEAR(g.latitude_deg, lat, 1e-9);
      }
}

// On a sphere the ellipsoid overload is the sphere placement, bit for bit.
TEST(Camera, SphereShapeIsTheSpherePlacementBitForBit) {
  const GeodeticPose pose{22.1, -98.4, 2.0, 60.0, -10.0, 0.0};
  const double ground = 6371000.0 + 1234.5;
  const Camera a = cameraFromPose(pose, ground, 6371000.0, 1.5);
  const Camera b = cameraFromPose(pose, ground, Ellipsoid::sphere(6371000.0), 1.5);
  EXPECT_EQ(a.position_m, b.position_m);
  EXPECT_EQ(a.forward, b.forward);
  EXPECT_EQ(a.up, b.up);
  EXPECT_EQ(a.right, b.right);
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
