// Camera paths from other tools (planet/paths): hand-written KML tours and CZML documents reproduce
// camera poses recomputed here independently (GeographicLib and plain vector geometry), a path
// survives path -> KML -> path, malformed files name file:line:col, and the .path format's optional
// columns (height_ref, stop) round-trip.
#include "planet/paths/camera_path.h"
#include "planet/paths/camera_path_file.h"
#include "planet/paths/czml_path.h"
#include "planet/paths/kml_tour.h"
#include "planet/paths/kml_view.h"

#include <gtest/gtest.h>
#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace globe {
namespace {

constexpr double kR = kKmlSphereRadius_m;  // the sphere the tour's LookAts are solved on
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kPosition_m = 0.01;  // 1 cm
constexpr double kAngle_deg = 0.01;

std::string dataPath(const std::string& name) { return std::string(GLOBE_SOURCE_DIR) + "/tests/data/" + name; }

CameraPath load(const std::string& name) {
  auto r = loadCameraPath(dataPath(name));
  EXPECT_TRUE(r.ok()) << r.error().format();
  return std::move(r).value();
}

// Ground `groundAbove_m` above the sphere everywhere: ground-relative heights move with it,
// sphere-relative ones must not.
GroundRadiusFn groundAt(double groundAbove_m) {
  return [groundAbove_m](const glm::dvec3&) { return kR + groundAbove_m; };
}

glm::dvec3 onSphere(double lat, double lon, double h) {
  GeographicLib::Geocentric sphere(kR, 0.0);
  glm::dvec3 p;
  sphere.Forward(lat, lon, h, p.x, p.y, p.z);
  return p;
}

struct Enu {
  glm::dvec3 e, n, u;
};
Enu enuAt(double lat, double lon) {
  double la = lat * kDeg, lo = lon * kDeg;
  return {{-std::sin(lo), std::cos(lo), 0},
          {-std::sin(la) * std::cos(lo), -std::sin(la) * std::sin(lo), std::cos(la)},
          {std::cos(la) * std::cos(lo), std::cos(la) * std::sin(lo), std::sin(la)}};
}

// Heading (clockwise from north) and pitch (up positive) of a view direction, degrees.
glm::dvec2 headingPitch_deg(const glm::dvec3& forward, double lat, double lon) {
  Enu f = enuAt(lat, lon);
  glm::dvec3 d = glm::normalize(forward);
  return {std::atan2(glm::dot(d, f.e), glm::dot(d, f.n)) / kDeg, std::asin(glm::dot(d, f.u)) / kDeg};
}

double angleDiff_deg(double a, double b) { return std::remainder(a - b, 360.0); }

// A KML LookAt solved independently: the camera in the target's local east/north/up frame.
struct LookAtExpectation {
  glm::dvec3 eye, target;
  double lat, lon;
};
LookAtExpectation expectLookAt(double lat, double lon, double alt, double heading, double tilt, double range) {
  GeographicLib::LocalCartesian local(lat, lon, alt, GeographicLib::Geocentric(kR, 0.0));
  const double h = heading * kDeg, t = tilt * kDeg;
  // The camera stands opposite to where it looks, `tilt` from the target's vertical.
  double x = -range * std::sin(t) * std::sin(h), y = -range * std::sin(t) * std::cos(h), z = range * std::cos(t);
  LookAtExpectation out;
  double eyeH;
  local.Reverse(x, y, z, out.lat, out.lon, eyeH);
  out.eye = onSphere(out.lat, out.lon, eyeH);
  out.target = onSphere(lat, lon, alt);
  return out;
}

TEST(KmlImport, LookAtRelativeToGroundIsTheCameraAtRangeFromTheTarget) {
  CameraPath path = load("tour.kml");
  LookAtExpectation want = expectLookAt(22.1, -98.3, 100, 30, 60, 5000);
  // The ground is the sphere here, as the importer assumes under a ground-relative LookAt.
  EXPECT_LT(glm::length(path.positionAt(0, groundAt(0), kR) - want.eye), kPosition_m);
  GeodeticPose pose = path.poseAt(0);
  glm::dvec2 hp = headingPitch_deg(want.target - want.eye, want.lat, want.lon);
  EXPECT_LT(std::abs(angleDiff_deg(pose.heading_deg, hp.x)), kAngle_deg);
  EXPECT_NEAR(pose.pitch_deg, hp.y, kAngle_deg);
  EXPECT_NEAR(pose.roll_deg, 0.0, kAngle_deg);
  EXPECT_EQ(path.keyframes()[0].heightReference, HeightReference::ground);
  // On raised ground the whole view rises with it.
  EXPECT_LT(
      glm::length(path.positionAt(0, groundAt(3000), kR) - glm::normalize(want.eye) * (glm::length(want.eye) + 3000)),
      kPosition_m);
}

TEST(KmlImport, CameraAndWaitGiveTheWrittenPoseAndHold) {
  CameraPath path = load("tour.kml");
  for (double t : {4.0, 5.0, 6.0}) {  // the FlyTo's end, then the gx:Wait holding it
    SCOPED_TRACE(t);
    EXPECT_LT(glm::length(path.positionAt(t, groundAt(3000), kR) - onSphere(22.15, -98.2, 3000 + 1500)), kPosition_m);
    GeodeticPose p = path.poseAt(t);
    EXPECT_NEAR(p.heading_deg, 90.0, kAngle_deg);
    EXPECT_NEAR(p.pitch_deg, 75.0 - 90.0, kAngle_deg);  // KML tilt 75 is 15 degrees below the horizon
    EXPECT_NEAR(p.roll_deg, -5.0, kAngle_deg);          // KML rolls left for positive values
  }
}

TEST(KmlImport, AbsoluteAltitudesAreAboveTheSphereWhateverTheGround) {
  CameraPath path = load("tour.kml");
  ASSERT_EQ(path.keyframes().size(), 5u);
  EXPECT_EQ(path.keyframes()[3].time_s, 9.0);  // 4 + 2 (Wait) + 3; gx:AnimatedUpdate takes no time
  EXPECT_EQ(path.keyframes()[3].heightReference, HeightReference::sphere);
  EXPECT_LT(glm::length(path.positionAt(9, groundAt(3000), kR) - onSphere(22.2, -98.1, 12000)), kPosition_m);
  EXPECT_NEAR(path.poseAt(9).pitch_deg, -45.0, kAngle_deg);
  // A LookAt straight down (tilt 0): range above the target, looking down, heading kept.
  EXPECT_LT(glm::length(path.positionAt(12, groundAt(3000), kR) - onSphere(22.25, -98.0, 29000)), kPosition_m);
  EXPECT_NEAR(path.poseAt(12).pitch_deg, -90.0, kAngle_deg);
  EXPECT_NEAR(path.poseAt(12).heading_deg, 45.0, kAngle_deg);
}

TEST(KmlImport, BounceFlyTosAndTheTourEndsComeToRest) {
  CameraPath path = load("tour.kml");
  const auto& k = path.keyframes();
  EXPECT_TRUE(k[0].stop);
  EXPECT_TRUE(k[1].stop && k[2].stop);  // around the Wait
  EXPECT_TRUE(k[3].stop);               // the last FlyTo bounces, so it starts at rest
  EXPECT_TRUE(k[4].stop);
  // Zero speed at a stop: the camera moves much less in the first millisecond than on average.
  double early = glm::length(path.positionAt(9.001, groundAt(0), kR) - path.positionAt(9.0, groundAt(0), kR));
  double average = glm::length(path.positionAt(12, groundAt(0), kR) - path.positionAt(9, groundAt(0), kR)) / 3000.0;
  EXPECT_LT(early, 0.05 * average);
}

// The CZML body axes (x forward, y left, z up) in the Earth-fixed frame.
glm::dvec3 czmlForward(double x, double y, double z, double w) { return glm::dquat(w, x, y, z) * glm::dvec3(1, 0, 0); }

TEST(CzmlImport, SampledCartographicPositionsAndQuaternions) {
  CameraPath path = load("track.czml");
  ASSERT_EQ(path.keyframes().size(), 3u);  // orientation's epoch is 5 s later: the same three times
  struct Sample {
    double t, lon, lat, h, qx, qy, qz, qw, heading, pitch, roll;
  };
  const Sample samples[] = {
      {0, -98.3, 22.1, 9000, 0.446207619783956, -0.10996876702283, 0.343858986870199, 0.818881326856838, 45, -20, 0},
      {10, -98.25, 22.12, 9500, 0.552071107402109, 0.021028471604888, 0.266165973718352, 0.789893011861944, 60, -25,
       10},
      {20, -98.2, 22.15, 8000, 0.492475420847289, 0.122578192894434, 0.160719810828579, 0.846529201442718, 80, -30,
       -5}};
  for (const Sample& s : samples) {
    SCOPED_TRACE(s.t);
    EXPECT_LT(glm::length(path.positionAt(s.t, groundAt(2000), kR) - onSphere(s.lat, s.lon, s.h)), kPosition_m);
    GeodeticPose p = path.poseAt(s.t);
    glm::dvec2 hp = headingPitch_deg(czmlForward(s.qx, s.qy, s.qz, s.qw), s.lat, s.lon);
    EXPECT_LT(std::abs(angleDiff_deg(p.heading_deg, hp.x)), kAngle_deg);
    EXPECT_NEAR(p.pitch_deg, hp.y, kAngle_deg);
    // ... which are the angles the fixture's quaternions were made from.
    EXPECT_LT(std::abs(angleDiff_deg(p.heading_deg, s.heading)), kAngle_deg);
    EXPECT_NEAR(p.pitch_deg, s.pitch, kAngle_deg);
    EXPECT_NEAR(p.roll_deg, s.roll, kAngle_deg);
  }
}

TEST(CzmlImport, CartesianPositionsWithIsoTimesAreWgs84) {
  CameraPath path = load("track_cartesian.czml");
  ASSERT_EQ(path.keyframes().size(), 2u);
  EXPECT_DOUBLE_EQ(path.endTime_s(), 8.5);
  // The fixture's Earth-fixed points were made from these WGS84 coordinates.
  const GeodeticPose& a = path.keyframes()[0].pose;
  EXPECT_NEAR(a.latitude_deg, 22.10, 1e-9);
  EXPECT_NEAR(a.longitude_deg, -98.30, 1e-9);
  EXPECT_NEAR(a.height_m, 9000, 1e-3);
  EXPECT_NEAR(a.heading_deg, 45, kAngle_deg);
  EXPECT_NEAR(path.keyframes()[1].pose.latitude_deg, 22.11, 1e-9);
  EXPECT_NEAR(path.keyframes()[1].pose.height_m, 9200, 1e-3);
}

TEST(CzmlImport, Iso8601) {
  EXPECT_EQ(parseIso8601_s("1970-01-01T00:00:00Z"), 0.0);
  EXPECT_EQ(parseIso8601_s("2000-03-01T00:00:01.5Z"), 951868801.5);
  EXPECT_EQ(parseIso8601_s("2000-03-01T02:00:00+02:00"), 951868800.0);
  EXPECT_FALSE(parseIso8601_s("yesterday"));
  EXPECT_FALSE(parseIso8601_s("2000-03-01T00:00:00"));  // no zone: ambiguous
}

void expectSamePath(const CameraPath& a, const CameraPath& b) {
  ASSERT_EQ(a.keyframes().size(), b.keyframes().size());
  for (std::size_t i = 0; i < a.keyframes().size(); ++i) {
    SCOPED_TRACE(i);
    const PathKeyframe &x = a.keyframes()[i], &y = b.keyframes()[i];
    EXPECT_NEAR(x.time_s - a.startTime_s(), y.time_s - b.startTime_s(), 1e-9);
    EXPECT_NEAR(x.pose.latitude_deg, y.pose.latitude_deg, 1e-12);
    EXPECT_NEAR(x.pose.longitude_deg, y.pose.longitude_deg, 1e-12);
    EXPECT_NEAR(x.pose.height_m, y.pose.height_m, 1e-9 * x.pose.height_m);
    EXPECT_NEAR(x.pose.heading_deg, y.pose.heading_deg, 1e-12);
    EXPECT_NEAR(x.pose.pitch_deg, y.pose.pitch_deg, 1e-12);
    EXPECT_NEAR(x.pose.roll_deg, y.pose.roll_deg, 1e-12);
    EXPECT_EQ(x.heightReference, y.heightReference);
  }
}

TEST(KmlExport, RoundTripGivesThePathBack) {
  for (const char* name : {"flyover.path", "polar-crossing.path"}) {
    SCOPED_TRACE(name);
    auto path = loadCameraPath(std::string(GLOBE_SOURCE_DIR) + "/assets/paths/" + name);
    ASSERT_TRUE(path.ok()) << path.error().format();
    auto back = parseKmlTour(formatKmlTour(*path, name), "export.kml");
    ASSERT_TRUE(back.ok()) << back.error().format();
    expectSamePath(*path, *back);
  }
  // Imported tours keep their height references, holds and rests through export and import.
  CameraPath tour = load("tour.kml");
  auto again = parseKmlTour(formatKmlTour(tour, "tour"), "export.kml");
  ASSERT_TRUE(again.ok()) << again.error().format();
  expectSamePath(tour, *again);
  for (std::size_t i = 0; i < tour.keyframes().size(); ++i)
    EXPECT_EQ(tour.keyframes()[i].stop, again->keyframes()[i].stop) << i;
}

std::string errorOf(const std::string& name) {
  auto r = loadCameraPath(dataPath("bad_paths/" + name));
  EXPECT_FALSE(r.ok()) << name;
  if (r.ok()) return "";
  std::string text = r.error().format();
  std::string prefix = dataPath("bad_paths/");
  return text.rfind(prefix, 0) == 0 ? text.substr(prefix.size()) : text;
}

TEST(PathImportErrors, NameFileLineColumnAndField) {
  EXPECT_EQ(errorOf("syntax.kml"), "syntax.kml:6:7: invalid XML: Start-end tags mismatch");
  EXPECT_EQ(errorOf("tilt.kml"), "tilt.kml:7:12: tilt: 'abc' is not a finite number");
  EXPECT_EQ(errorOf("no_tour.kml"), "no_tour.kml:1: gx:Tour: no tour in this KML file (expected a gx:Tour element)");
  EXPECT_EQ(errorOf("syntax.czml").substr(0, 29), "syntax.czml:3:73: invalid JSO");
  EXPECT_EQ(errorOf("quaternion.czml"),
            "quaternion.czml:6:21: unitQuaternion: expected 4 numbers, or samples of a time and 4 numbers, got 9 "
            "values");
}

TEST(PathFileColumns, HeightReferenceAndStopRoundTrip) {
  const std::string text = std::string(kCameraPathHeader) +
                           " height_ref stop\n"
                           "0 22 -98 5000 10 -20 0 sphere 1\n"
                           "2 22.01 -98 300 10 -20 0 ground 0\n"
                           "4 22.02 -98 9000 10 -20 0 sphere 1\n";
  auto path = parseCameraPath(text, "t.path");
  ASSERT_TRUE(path.ok()) << path.error().format();
  EXPECT_EQ(path->keyframes()[0].heightReference, HeightReference::sphere);
  EXPECT_TRUE(path->keyframes()[0].stop);
  EXPECT_FALSE(path->keyframes()[1].stop);
  EXPECT_EQ(formatCameraPath(*parseCameraPath(formatCameraPath(*path), "u.path")), formatCameraPath(*path));
  // Sphere heights ignore the ground; the blend between references is continuous.
  EXPECT_LT(glm::length(path->positionAt(0, groundAt(4000), kR) - onSphere(22, -98, 5000)), kPosition_m);
  EXPECT_LT(glm::length(path->positionAt(2, groundAt(4000), kR) - onSphere(22.01, -98, 4300)), kPosition_m);
  EXPECT_NEAR(path->sphereWeightAt(1.0), 0.5, 1e-12);
  // Ground-only paths keep the seven columns.
  EXPECT_EQ(formatCameraPath(*parseCameraPath(std::string(kCameraPathHeader) + "\n0 1 2 3 4 5 6\n1 1 2 4 4 5 6\n", "v"))
                .find("height_ref"),
            std::string::npos);
}

TEST(PathFileColumns, Errors) {
  auto bad = [](const std::string& extra, const std::string& row) {
    auto r = parseCameraPath(
        std::string(kCameraPathHeader) + extra + "\n0 1 2 3 4 5 6" + row + "\n1 1 2 3 4 5 6" + row + "\n", "x.path");
    return r.ok() ? std::string("ok") : r.error().format();
  };
  EXPECT_EQ(bad(" speed", " 1"),
            "x.path:1: unknown column 'speed' in the header (after the seven fixed columns only height_ref, stop, "
            "sun_azimuth_deg and sun_elevation_deg may follow, once each)");
  EXPECT_EQ(bad(" height_ref", " sea"), "x.path:2: height_ref must be 'ground' or 'sphere', got 'sea'");
  EXPECT_EQ(bad(" stop", " yes"), "x.path:2: stop must be 0 or 1, got 'yes'");
  EXPECT_EQ(bad(" stop", ""), "x.path:2: missing field stop (expected 8 fields, found 7)");
}

}  // namespace
}  // namespace globe
