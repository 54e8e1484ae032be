// Camera paths: the file format (every asset parses, every malformed case gives its exact one-line
// error, the writer round-trips bit-exactly) and the interpolation (exact keyframe hits, continuity of
// position and speed, log-altitude, +-180° and pole crossings, level flight, hovering).
#include "planet/paths/camera_path.h"
#include "planet/camera/camera_orientation.h"
#include "planet/paths/camera_path_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>

namespace globe {
namespace {

constexpr double kR = 6371000.0;  // the Earth-like planet's radius, metres
const GroundRadiusFn kSphere = [](const glm::dvec3&) { return kR; };
const std::string kHeader = std::string(kCameraPathHeader) + "\n";

std::string assetPath(const std::string& name) { return std::string(GLOBE_SOURCE_DIR) + "/assets/paths/" + name; }

CameraPath load(const std::string& name) {
  auto r = loadCameraPath(assetPath(name));
  EXPECT_TRUE(r.ok()) << r.error().format();
  return std::move(r).value();
}

CameraPath parse(const std::string& text) {
  auto r = parseCameraPath(text, "t.path");
  EXPECT_TRUE(r.ok()) << r.error().format();
  return std::move(r).value();
}

double angle(const glm::dvec3& a, const glm::dvec3& b) {
  return 2.0 * std::atan2(glm::length(a - b), glm::length(a + b));
}

// Rotation angle (radians) between two orientations.
double turnAngle(const glm::dquat& a, const glm::dquat& b) {
  double d = std::min(1.0, std::abs(glm::dot(glm::normalize(a), glm::normalize(b))));
  return 2.0 * std::acos(d);
}

const char* kAssets[] = {"flyover.path", "seam-traverse.path", "polar-crossing.path", "turn-360.path"};

// ---- format -------------------------------------------------------------------------------------

TEST(CameraPathFile, EveryAssetParses) {
  for (const char* name : kAssets) {
    auto r = loadCameraPath(assetPath(name));
    ASSERT_TRUE(r.ok()) << name << ": " << r.error().format();
    EXPECT_GE(r->keyframes().size(), 2u) << name;
    EXPECT_GT(r->duration_s(), 0.0) << name;
  }
}

TEST(CameraPathFile, FlyoverFollowsTheSourceFlight) {
  CameraPath p = load("flyover.path");
  EXPECT_EQ(p.startTime_s(), 0.0);
  EXPECT_NEAR(p.duration_s(), 20.0, 2.0);
  EXPECT_GE(p.heightAt(0), 4e5);  // outside the atmosphere
  EXPECT_LE(p.heightAt(0), 1e6);
  EXPECT_GE(p.heightAt(p.endTime_s()), 2e7);  // whole-planet view
  // The key frames rendered by the benchmark are authored keyframes.
  for (double t : {0.0, 7.0, 12.0, 18.0}) {
    bool found = false;
    for (const auto& k : p.keyframes()) found = found || k.time_s == t;
    EXPECT_TRUE(found) << t;
  }
  // Hovers for seconds at tens of metres, then flies low and fast over the mountains.
  double hover_s = 0;
  for (double t = 0; t <= p.endTime_s(); t += 0.01)
    if (p.heightAt(t) < 100 && glm::length(p.positionAt(t + 0.01, kSphere) - p.positionAt(t, kSphere)) < 0.01)
      hover_s += 0.01;
  EXPECT_GE(hover_s, 2.0);
  double lowAndFast_s = 0;
  for (double t = 7; t < 12; t += 0.01) {
    double speed = glm::length(p.positionAt(t + 0.01, kSphere) - p.positionAt(t, kSphere)) / 0.01;
    if (p.heightAt(t) < 2000 && speed > 1000) lowAndFast_s += 0.01;
  }
  EXPECT_GE(lowAndFast_s, 3.0);
}

TEST(CameraPathFile, SeamTraverseCrossesTheFiveFoldVertexAtGroundLevel) {
  CameraPath p = load("seam-traverse.path");
  const glm::dvec3 vertex = directionFromLatLon(std::atan(0.5) * 180 / 3.14159265358979323846, 0);
  double closest_m = 1e30;
  for (double t = p.startTime_s(); t <= p.endTime_s(); t += 0.01) {
    closest_m = std::min(closest_m, angle(p.directionAt(t), vertex) * kR);
    EXPECT_LE(p.heightAt(t), 10.0);
  }
  EXPECT_LT(closest_m, 0.01);
}

TEST(CameraPathFile, PolarCrossingReachesThePoleLow) {
  CameraPath p = load("polar-crossing.path");
  double maxLat = -90;
  for (double t = p.startTime_s(); t <= p.endTime_s(); t += 0.01) maxLat = std::max(maxLat, p.poseAt(t).latitude_deg);
  EXPECT_GT(maxLat, 89.9999);
  EXPECT_LT(p.heightAt(10), 1000);
}

TEST(CameraPathFile, Turn360StandsStillAndTurnsOnce) {
  CameraPath p = load("turn-360.path");
  glm::dvec3 start = p.positionAt(0, kSphere);
  double turned_rad = 0;
  glm::dvec3 forward = basisFromOrientation(p.orientationAt(0)).forward;
  for (double t = 0.05; t <= p.endTime_s() + 1e-9; t += 0.05) {
    EXPECT_LT(glm::length(p.positionAt(t, kSphere) - start), 1e-6) << t;
    EXPECT_NEAR(p.heightAt(t), 2.0, 1e-9);
    glm::dvec3 f = basisFromOrientation(p.orientationAt(t)).forward;
    turned_rad += angle(forward, f);
    forward = f;
  }
  EXPECT_NEAR(turned_rad, 2 * 3.14159265358979323846, 1e-6);
}

TEST(CameraPathFile, MalformedInputGivesOneLineWithFileAndLine) {
  const std::string h = kHeader;
  const std::string ok0 = "0 0 0 10 0 0 0\n", ok1 = "1 0 0.001 10 0 0 0\n";
  struct Case {
    std::string text;
    std::string message;
  } cases[] = {
      {"", "t.path:1: empty camera path: expected the header '" + std::string(kCameraPathHeader) + "'"},
      {"# nothing but comments\n\n",
       "t.path:2: empty camera path: expected the header '" + std::string(kCameraPathHeader) + "'"},
      {"t lat lon\n", "t.path:1: expected the header '" + std::string(kCameraPathHeader) + "', got 't lat lon'"},
      {"0 0 0 10 0 0 0\n",
       "t.path:1: expected the header '" + std::string(kCameraPathHeader) + "', got '0 0 0 10 0 0 0'"},
      {h, "t.path:1: a camera path needs at least 2 keyframes, found 0"},
      {h + ok0 + "# end\n", "t.path:3: a camera path needs at least 2 keyframes, found 1"},
      {h + ok0 + "1 abc 0 10 0 0 0\n", "t.path:3: lat_deg 'abc' is not a number"},
      {h + ok0 + "1 0 1.5.3 10 0 0 0\n", "t.path:3: lon_deg '1.5.3' is not a number"},
      {h + ok0 + "1 0 0 10m 0 0 0\n", "t.path:3: height_m '10m' is not a number"},
      {h + ok0 + "1 0 0 10 0,5 0 0\n", "t.path:3: heading_deg '0,5' is not a number"},
      {h + ok0 + "1 nan 0 10 0 0 0\n", "t.path:3: lat_deg must be finite, got 'nan'"},
      {h + ok0 + "1 0 0 inf 0 0 0\n", "t.path:3: height_m must be finite, got 'inf'"},
      {h + ok0 + "1 0 0 10 0 -NaN 0\n", "t.path:3: pitch_deg must be finite, got '-NaN'"},
      {h + ok0 + "1 0 0 1e999 0 0 0\n", "t.path:3: height_m '1e999' is out of range"},
      {h + ok0 + "1 0 0 10 0 0\n", "t.path:3: missing field roll_deg (expected 7 fields, found 6)"},
      {h + ok0 + "1 0 0\n", "t.path:3: missing field height_m (expected 7 fields, found 3)"},
      {h + ok0 + "1 0 0 10 0 0 0 7\n", "t.path:3: too many fields (expected 7, found 8)"},
      {h + ok0 + "0 0 0.001 10 0 0 0\n", "t.path:3: t_s must increase: 0 is not after the previous keyframe's 0"},
      {h + "5 0 0 10 0 0 0\n\n# x\n" + "2 0 0 10 0 0 0\n",
       "t.path:5: t_s must increase: 2 is not after the previous keyframe's 5"},
      {h + ok0 + "1 90.5 0 10 0 0 0\n", "t.path:3: lat_deg must be within [-90, 90]"},
      {h + "0 -91 0 10 0 0 0\n" + ok1, "t.path:2: lat_deg must be within [-90, 90]"},
      {h + ok0 + "1 0 0 10 0 -90.01 0\n", "t.path:3: pitch_deg must be within [-90, 90]"},
      {h + ok0 + "1 0 0 0 0 0 0\n", "t.path:3: height_m must be within (0, 1e12] metres above the ground"},
      {h + ok0 + "1 0 0 -5 0 0 0\n", "t.path:3: height_m must be within (0, 1e12] metres above the ground"},
      {h + ok0 + "1 0 0 2e12 0 0 0\n", "t.path:3: height_m must be within (0, 1e12] metres above the ground"},
      {h + ok0 + "1 0 1e308 10 0 0 0\n", "t.path:3: lon_deg must be within [-360, 360]"},
      {h + "-1e308 0 0 10 0 0 0\n" + ok1, "t.path:2: t_s must be within [-1000000, 1000000] seconds"},
      {h + ok0 + "1e308 0 0.001 10 0 0 0\n", "t.path:3: t_s must be within [-1000000, 1000000] seconds"},
      {h + ok0 + "1000000 0 0.001 10 0 0 0\n", "t.path:3: the path lasts 1000000 s, more than the limit of 3600 s"},
      {h + ok0 + "1 0 170 10 0 0 0\n",
       "t.path:3: keyframe is 170.0 degrees of arc from the previous one (at most 150); add keyframes between them"},
      {h + ok0 + "1 0 0 10 180 0 0\n",
       "t.path:3: the camera turns by 180.0 degrees since the previous keyframe (at most 179); add keyframes "
       "between them"},
  };
  for (const auto& c : cases) {
    auto r = parseCameraPath(c.text, "t.path");
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().format(), c.message) << c.text;
  }
}

TEST(CameraPathFile, AcceptsCommentsBlankLinesTabsCrLfAndSigns) {
  auto r = parseCameraPath("# a path\r\n\r\n" + std::string(kCameraPathHeader) + "  # columns\r\n" +
                               "0\t+1.5 -2 1e3 0 -0 0   # start\r\n2 1.5 -2 +1e3 10 -10 0\r\n",
                           "t.path");
  ASSERT_TRUE(r.ok()) << r.error().format();
  ASSERT_EQ(r->keyframes().size(), 2u);
  EXPECT_EQ(r->keyframes()[0].pose.latitude_deg, 1.5);
  EXPECT_EQ(r->keyframes()[0].pose.height_m, 1000.0);
  EXPECT_TRUE(std::signbit(r->keyframes()[0].pose.pitch_deg));
  EXPECT_EQ(r->keyframes()[0].line, 4);
  EXPECT_EQ(r->keyframes()[1].line, 5);
}

TEST(CameraPathFile, UnreadableFile) {
  auto r = loadCameraPath("/nonexistent/dir/x.path");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().format(), "/nonexistent/dir/x.path: cannot open camera path file: No such file or directory");
  auto d = loadCameraPath(assetPath(""));  // a directory
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error().format(), assetPath("") + ": cannot read camera path file: it is a directory");
}

TEST(CameraPathFile, InMemoryKeyframesAreNamedByIndex) {
  std::vector<PathKeyframe> keys = {{0, {0, 0, 10, 0, 0, 0}, 0}, {1, {0, 0, 10, 0, std::nan(""), 0}, 0}};
  auto r = CameraPath::create(keys, "");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().format(), "keyframe 2: pitch_deg must be finite");
  auto one = CameraPath::create({keys[0]}, "rec.path");
  ASSERT_FALSE(one.ok());
  EXPECT_EQ(one.error().format(), "rec.path: a camera path needs at least 2 keyframes, found 1");
}

void expectSameBits(const CameraPath& a, const CameraPath& b) {
  ASSERT_EQ(a.keyframes().size(), b.keyframes().size());
  // Bit for bit, except that -0 is written as 0 (a person editing the file should not meet "-0").
  auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); };
  for (std::size_t i = 0; i < a.keyframes().size(); ++i) {
    const auto &x = a.keyframes()[i], &y = b.keyframes()[i];
    EXPECT_EQ(bits(x.time_s), bits(y.time_s)) << i;
    EXPECT_EQ(bits(x.pose.latitude_deg), bits(y.pose.latitude_deg)) << i;
    EXPECT_EQ(bits(x.pose.longitude_deg), bits(y.pose.longitude_deg)) << i;
    EXPECT_EQ(bits(x.pose.height_m), bits(y.pose.height_m)) << i;
    EXPECT_EQ(bits(x.pose.heading_deg), bits(y.pose.heading_deg)) << i;
    EXPECT_EQ(bits(x.pose.pitch_deg), bits(y.pose.pitch_deg)) << i;
    EXPECT_EQ(bits(x.pose.roll_deg), bits(y.pose.roll_deg)) << i;
  }
}

TEST(CameraPathFile, WriterRoundTripsBitExactly) {
  for (const char* name : kAssets) {
    CameraPath p = load(name);
    expectSameBits(p, parse(formatCameraPath(p)));
  }
  // Awkward doubles: thirds, tiny and huge magnitudes, negative zero, values near the range limits.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<PathKeyframe> keys;
  double t = -1.0 / 3.0;
  GeodeticPose pose{-1.0 / 3.0, -179.9, 1e-7, 0.1, -0.2, 1.0 / 7.0};
  for (int i = 0; i < 200; ++i) {
    // A random walk: small steps keep every segment within the arc and turn limits.
    t += 1e-3 + u(rng) / 7.0;
    pose.latitude_deg = std::clamp(pose.latitude_deg + u(rng) - 0.5, -90.0, 90.0);
    pose.longitude_deg += u(rng) - 0.5;
    pose.height_m = std::exp(-20 + u(rng) * 40);
    pose.heading_deg += u(rng) * 10 - 5;
    pose.pitch_deg = std::clamp(pose.pitch_deg + u(rng) * 10 - 5, -90.0, 90.0);
    pose.roll_deg = u(rng) * 20 - 10;
    if (i % 17 == 0) pose.roll_deg = -0.0;
    keys.push_back({t, pose, 0});
  }
  auto p = CameraPath::create(keys);
  ASSERT_TRUE(p.ok()) << p.error().format();
  CameraPath back = parse(formatCameraPath(*p));
  expectSameBits(*p, back);
  EXPECT_FALSE(std::signbit(back.keyframes()[0].pose.roll_deg));

  // Through a file, atomically written.
  std::string file = (std::filesystem::temp_directory_path() / "globe_camera_path_roundtrip.path").string();
  ASSERT_TRUE(saveCameraPath(file, *p).ok());
  auto loaded = loadCameraPath(file);
  ASSERT_TRUE(loaded.ok()) << loaded.error().format();
  expectSameBits(*p, *loaded);
  std::filesystem::remove(file);
}

// Numbers as a person would write them: the shortest decimal that reads back to the same double.
TEST(CameraPathFile, WriterUsesTheShortestRoundTrippingNumbers) {
  auto p = parseCameraPath(
      std::string(kCameraPathHeader) + "\n0 22.12 -0 1000 0.1 -0 0\n2.5 22.13 1e-7 1000 90 -30 0\n", "w.path");
  ASSERT_TRUE(p.ok()) << p.error().format();
  const std::string text = formatCameraPath(*p);
  EXPECT_NE(text.find("\n0 22.12 0 1000 0.1 0 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n2.5 22.13 1e-07 1000 90 -30 0\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("-0 "), std::string::npos) << text;
}

TEST(CameraPathFile, SunColumnsAreReadCheckedAndWritten) {
  const std::string h = std::string(kCameraPathHeader) + " sun_azimuth_deg sun_elevation_deg\n";
  auto p = parseCameraPath(h + "0 0 0 10 0 0 0 250 -3.5\n1 0 0.001 10 0 0 0 -30 90\n", "s.path");
  ASSERT_TRUE(p.ok()) << p.error().format();
  ASSERT_TRUE(p->keyframes()[0].sun.has_value());
  EXPECT_EQ(p->keyframes()[0].sun->azimuth_deg, 250.0);
  EXPECT_EQ(p->keyframes()[0].sun->elevation_deg, -3.5);
  const std::string text = formatCameraPath(*p);
  EXPECT_NE(text.find("sun_azimuth_deg sun_elevation_deg"), std::string::npos);
  auto back = parseCameraPath(text, "back.path");
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->keyframes()[1].sun->azimuth_deg, -30.0);
  EXPECT_EQ(back->keyframes()[1].sun->elevation_deg, 90.0);
  EXPECT_FALSE(load("flyover.path").keyframes()[0].sun.has_value());  // no columns, no sun
  const std::string ok0 = "0 0 0 10 0 0 0 0 45\n";
  struct Case {
    std::string text;
    std::string message;
  } cases[] = {
      {std::string(kCameraPathHeader) + " sun_azimuth_deg\n0 0 0 10 0 0 0 0\n",
       "t.path:1: sun_azimuth_deg and sun_elevation_deg go together: give both columns or neither"},
      {h + ok0 + "1 0 0.001 10 0 0 0 0 91\n", "t.path:3: sun_elevation_deg must be within [-90, 90], got '91'"},
      {h + ok0 + "1 0 0.001 10 0 0 0 east 10\n", "t.path:3: sun_azimuth_deg 'east' is not a number"},
      {h + ok0 + "1 0 0.001 10 0 0 0 0 nan\n", "t.path:3: sun_elevation_deg must be finite, got 'nan'"},
  };
  for (const auto& c : cases) {
    auto r = parseCameraPath(c.text, "t.path");
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().format(), c.message) << c.text;
  }
}

// ---- interpolation ------------------------------------------------------------------------------

TEST(CameraPathInterpolation, KeyframesAreHitExactly) {
  for (const char* name : kAssets) {
    CameraPath p = load(name);
    for (const auto& k : p.keyframes()) {
      GeodeticPose q = p.poseAt(k.time_s);
      EXPECT_EQ(q.latitude_deg, k.pose.latitude_deg);
      EXPECT_EQ(q.longitude_deg, k.pose.longitude_deg);
      EXPECT_EQ(q.height_m, k.pose.height_m);
      EXPECT_EQ(q.heading_deg, k.pose.heading_deg);
      EXPECT_EQ(q.pitch_deg, k.pose.pitch_deg);
      EXPECT_EQ(q.roll_deg, k.pose.roll_deg);
      Camera a = p.cameraAt(k.time_s, kR, 1.5, kSphere), b = cameraFromPose(k.pose, kR, kR, 1.5);
      EXPECT_EQ(a.position_m, b.position_m);
      EXPECT_EQ(a.forward, b.forward);
      EXPECT_EQ(a.up, b.up);
      // Approaching the keyframe from either side converges to it (no jump at the hit).
      for (double eps : {-1e-12, 1e-12}) {
        double t = k.time_s + eps * std::max(1.0, std::abs(k.time_s));
        if (t < p.startTime_s() || t > p.endTime_s()) continue;
        // Within what the local speed allows over |t - t_k| (the flyover's exit reaches 6e7 m/s).
        double probe = k.time_s + 1e-3 * (eps > 0 ? 1 : -1);
        double speed = glm::length(p.positionAt(probe, kSphere) - p.positionAt(k.time_s, kSphere)) / 1e-3;
        EXPECT_LE(glm::length(p.positionAt(t, kSphere) - p.positionAt(k.time_s, kSphere)),
                  4 * speed * std::abs(t - k.time_s) + 1e-6)
            << name;
        EXPECT_LT(turnAngle(p.orientationAt(t), p.orientationAt(k.time_s)), 1e-6) << name;
        EXPECT_NEAR(p.heightAt(t), k.pose.height_m, 1e-6 * k.pose.height_m) << name;
      }
    }
  }
}

// One-sided second-order finite differences of the position at t, from the left and from the right.
std::pair<glm::dvec3, glm::dvec3> oneSidedVelocities(const CameraPath& p, double t, double h) {
  auto P = [&](double u) { return p.positionAt(u, kSphere); };
  glm::dvec3 left = (3.0 * P(t) - 4.0 * P(t - h) + P(t - 2 * h)) / (2 * h);
  glm::dvec3 right = (-3.0 * P(t) + 4.0 * P(t + h) - P(t + 2 * h)) / (2 * h);
  return {left, right};
}

TEST(CameraPathInterpolation, PositionAndSpeedAreContinuousAtKeyframes) {
  for (const char* name : kAssets) {
    CameraPath p = load(name);
    const auto& keys = p.keyframes();
    for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
      double h = 1e-4 * std::min(keys[i].time_s - keys[i - 1].time_s, keys[i + 1].time_s - keys[i].time_s);
      auto [left, right] = oneSidedVelocities(p, keys[i].time_s, h);
      double speed = std::max(glm::length(left), glm::length(right));
      EXPECT_LE(glm::length(left - right), 1e-4 * speed + 1e-3)
          << name << " keyframe " << i << " speed " << speed << " m/s";
    }
  }
}

TEST(CameraPathInterpolation, SpeedIsContinuousOnAnIrregularPath) {
  // Uneven times, turns, altitude changes over five decades: a C1 curve stays C1.
  CameraPath p = parse(kHeader +
                       "0 10 20 500000 0 -30 0\n"
                       "1.5 11 21 20000 10 -20 5\n"
                       "2 11.2 21.5 300 40 -10 -5\n"
                       "5.5 11.5 21.4 30 60 0 0\n"
                       "6 11.6 21.6 3000 90 -45 20\n"
                       "9 13 25 1e6 100 -90 0\n");
  for (std::size_t i = 1; i + 1 < p.keyframes().size(); ++i) {
    double t = p.keyframes()[i].time_s;
    auto [left, right] = oneSidedVelocities(p, t, 1e-5);
    double speed = std::max(glm::length(left), glm::length(right));
    EXPECT_LE(glm::length(left - right), 1e-4 * speed + 1e-3) << "keyframe " << i << " speed " << speed;
  }
}

TEST(CameraPathInterpolation, AltitudeIsInterpolatedInLogSpace) {
  CameraPath p = parse(kHeader + "0 0 0 1e6 0 -90 0\n10 0 0.1 10 0 -90 0\n");
  // Half way in time is half way in decades: sqrt(1e6 * 10), not (1e6 + 10) / 2.
  EXPECT_NEAR(p.heightAt(5), std::sqrt(1e7), 1e-6 * std::sqrt(1e7));
  double previous = 2e6;
  for (double t = 0; t <= 10; t += 0.01) {
    double h = p.heightAt(t);
    EXPECT_LT(h, previous) << t;  // monotone descent
    previous = h;
  }
}

TEST(CameraPathInterpolation, HoveringKeyframesStandStillWithoutOvershoot) {
  // Down from orbit, hover at 10 m, back up: never below 10 m, never moving during the hover.
  CameraPath p = parse(kHeader +
                       "0 0 0 1e6 0 -90 0\n"
                       "4 1 1 10 0 0 0\n"
                       "7 1 1 10 30 0 0\n"
                       "10 3 3 1e6 30 -90 0\n");
  glm::dvec3 hover = p.positionAt(4, kSphere);
  for (double t = 0; t <= 10; t += 0.001) {
    EXPECT_GE(p.heightAt(t), 10.0 * (1 - 1e-12)) << t;
    if (t >= 4 && t <= 7) {
      EXPECT_LT(glm::length(p.positionAt(t, kSphere) - hover), 1e-6) << t;
    }
  }
}

// Largest step between consecutive samples (metres), for jump detection.
double largestStep_m(const CameraPath& p, double dt) {
  double largest = 0;
  glm::dvec3 prev = p.positionAt(p.startTime_s(), kSphere);
  for (double t = p.startTime_s() + dt; t <= p.endTime_s(); t += dt) {
    glm::dvec3 x = p.positionAt(t, kSphere);
    largest = std::max(largest, glm::length(x - prev));
    prev = x;
  }
  return largest;
}

TEST(CameraPathInterpolation, CrossesTheAntimeridianWithoutJumping) {
  // 179.5°E -> 179.5°W: 1° of longitude the short way, not 359° the long way.
  CameraPath p = parse(kHeader + "0 10 179.5 100 90 0 0\n5 10.2 -179.9 100 90 0 0\n10 10 -179.5 100 90 0 0\n");
  const double dt = 0.001, arc_m = 1.0 * 3.14159265358979323846 / 180 * kR;
  EXPECT_LT(largestStep_m(p, dt), 3.0 * arc_m / 10 * dt);
  for (double t = 0; t <= 10; t += 0.01) {
    GeodeticPose q = p.poseAt(t);
    EXPECT_GT(std::abs(q.longitude_deg), 179.4) << t;
    EXPECT_LE(q.longitude_deg, 180.0);
    EXPECT_GT(q.longitude_deg, -180.0);
    EXPECT_NEAR(q.heading_deg, 90, 1.0) << t;  // still flying east
    EXPECT_NEAR(q.pitch_deg, 0, 1e-9) << t;
  }
  EXPECT_LT(std::abs(glm::length(p.positionAt(2.5, kSphere)) - (kR + 100)), 1e-6);
}

TEST(CameraPathInterpolation, CrossesThePoleWithoutJumpingOrSpinning) {
  // Keyframes on either side of the pole; the pole itself is passed between them.
  CameraPath p = parse(kHeader + "0 89.9 10 300 0 -10 0\n10 89.9 -170 300 180 -10 0\n");
  EXPECT_LT(largestStep_m(p, 0.001), 2.0 * (0.2 * 3.14159265358979323846 / 180 * kR) / 10 * 0.001);
  EXPECT_GT(p.poseAt(5).latitude_deg, 89.99999);
  // The camera flies straight over: its view direction barely changes, though heading flips 0 -> 180.
  glm::dvec3 f0 = basisFromOrientation(p.orientationAt(0)).forward;
  for (double t = 0; t <= 10; t += 0.01) {
    glm::dvec3 f = basisFromOrientation(p.orientationAt(t)).forward;
    EXPECT_LT(angle(f0, f), 0.2 * 3.14159265358979323846 / 180 + 1e-9) << t;
    EXPECT_NEAR(p.poseAt(t).pitch_deg, -10, 1e-6) << t;
    EXPECT_NEAR(p.poseAt(t).roll_deg, 0, 1e-6) << t;
  }
  // The asset with a keyframe exactly at the pole: no jumps either.
  CameraPath asset = load("polar-crossing.path");
  EXPECT_LT(largestStep_m(asset, 0.001), 2.0);  // about 1.1 km/s
  glm::dquat prev = asset.orientationAt(0);
  for (double t = 0.001; t <= asset.endTime_s(); t += 0.001) {
    glm::dquat q = asset.orientationAt(t);
    EXPECT_LT(turnAngle(prev, q), 1e-3) << t;
    prev = q;
  }
}

TEST(CameraPathInterpolation, LevelKeyframesGiveALevelFlight) {
  // 60° of arc along no particular great circle, heading changing: pitch and roll stay 0.
  CameraPath p = parse(kHeader + "0 -20 10 500 30 0 0\n10 25 40 800 70 0 0\n20 40 -5 300 200 0 0\n");
  for (double t = 0; t <= 20; t += 0.05) {
    GeodeticPose q = p.poseAt(t);
    EXPECT_NEAR(q.pitch_deg, 0, 1e-9) << t;
    EXPECT_NEAR(q.roll_deg, 0, 1e-9) << t;
  }
}

TEST(CameraPathInterpolation, CameraMatchesTheInterpolatedOrientation) {
  CameraPath p = load("flyover.path");
  for (double t = 0.013; t < p.endTime_s(); t += 0.25) {
    Camera cam = p.cameraAt(t, kR, 16.0 / 9.0, kSphere);
    CameraBasis b = basisFromOrientation(p.orientationAt(t));
    EXPECT_LT(glm::length(cam.forward - b.forward), 1e-9) << t;
    EXPECT_LT(glm::length(cam.up - b.up), 1e-9) << t;
    EXPECT_LT(glm::length(cam.position_m - p.positionAt(t, kSphere)), 1e-6 * glm::length(cam.position_m)) << t;
  }
  // Outside the path's time range the ends are held.
  EXPECT_EQ(p.poseAt(-5).height_m, p.keyframes().front().pose.height_m);
  EXPECT_EQ(p.poseAt(1e9).height_m, p.keyframes().back().pose.height_m);
}

TEST(CameraPathInterpolation, TerrainFollowingUsesTheGroundCallback) {
  CameraPath p = load("turn-360.path");
  GroundRadiusFn mountain = [](const glm::dvec3&) { return kR + 7000.0; };
  EXPECT_NEAR(glm::length(p.positionAt(3.3, mountain)), kR + 7002.0, 1e-6);
}

// ---- orientation helpers ------------------------------------------------------------------------

TEST(CameraPathOrientation, PoseFromCameraInvertsCameraFromPose) {
  const GeodeticPose poses[] = {
      {0, 0, 100, 0, 0, 0},         {45, -120, 2, 30, -20, 10}, {-33, 179.9, 5e5, 250, 60, -170},
      {89.999, 10, 300, 0, -10, 0}, {90, 10, 100, 0, -10, 0},   {-90, -45, 1e7, 123, 45, 5},
      {10, 20, 50, 40, -90, 0},     {10, 20, 50, 40, 90, 0},    {-5, -179.999, 1, -170, 89.5, 30},
  };
  for (const auto& pose : poses) {
    Camera cam = cameraFromPose(pose, kR, kR, 1.0);
    GeodeticPose back = poseFromCamera(cam, kR);
    Camera again = cameraFromPose(back, kR, kR, 1.0);
    EXPECT_LT(glm::length(again.position_m - cam.position_m), 1e-6);
    EXPECT_LT(glm::length(again.forward - cam.forward), 1e-12);
    EXPECT_LT(glm::length(again.right - cam.right), 1e-12);
    EXPECT_LT(glm::length(again.up - cam.up), 1e-12);
    EXPECT_NEAR(back.height_m, pose.height_m, 1e-6);
    EXPECT_NEAR(back.pitch_deg, pose.pitch_deg, 1e-9);
    // Through the quaternion too.
    CameraBasis b = basisFromOrientation(orientationFromBasis(basisFromPose(pose)));
    EXPECT_LT(glm::length(b.forward - cam.forward), 1e-12);
    EXPECT_LT(glm::length(b.up - cam.up), 1e-12);
  }
}

}  // namespace
}  // namespace globe
