// CPU parts of the windowed viewer: deferred release by frame, the input-script format and the
// fly camera (altitude-scaled speed, never below the ground, stable at the poles).
#include "engine/viewer/fly_camera.h"
#include "engine/viewer/input_script.h"
#include "engine/vk/deferred_release_queue.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace globe {
namespace {

constexpr double kR = 6371000.0;

// Appends its name to a log when destroyed, so tests can see when and in which order.
struct Tracked {
  Tracked(std::vector<std::string>* log, std::string name) : log_(log), name_(std::move(name)) {}
  Tracked(Tracked&& o) noexcept : log_(std::exchange(o.log_, nullptr)), name_(std::move(o.name_)) {}
  ~Tracked() {
    if (log_) log_->push_back(name_);
  }
  std::vector<std::string>* log_;
  std::string name_;
};

TEST(DeferredReleaseQueue, ReleasesOnlyCompletedFramesInRetirementOrder) {
  std::vector<std::string> log;
  vk::DeferredReleaseQueue q;
  q.retire(5, Tracked(&log, "a5"));
  q.retire(3, Tracked(&log, "b3"));
  q.retire(5, Tracked(&log, "c5"));
  q.retire(7, std::make_unique<Tracked>(&log, "d7"));
  EXPECT_EQ(q.size(), 4u);
  EXPECT_EQ(q.collect(2), 0u);
  EXPECT_TRUE(log.empty());
  EXPECT_EQ(q.collect(4), 1u);
  EXPECT_EQ(log, std::vector<std::string>({"b3"}));
  EXPECT_EQ(q.collect(6), 2u);
  EXPECT_EQ(log, std::vector<std::string>({"b3", "a5", "c5"}));
  EXPECT_EQ(q.size(), 1u);
  q.releaseAll();
  EXPECT_EQ(log.back(), "d7");
  EXPECT_EQ(q.size(), 0u);
}

TEST(DeferredReleaseQueue, DestructorReleasesTheRest) {
  std::vector<std::string> log;
  {
    vk::DeferredReleaseQueue q;
    q.retire(100, Tracked(&log, "x"));
  }
  EXPECT_EQ(log, std::vector<std::string>({"x"}));
}

TEST(InputScript, ParsesEveryEventKindSortedByFrame) {
  auto s = parseInputScript(
      "# comment\n"
      "\n"
      "10 KEY W down   # trailing comment\n"
      "2 key escape UP\n"
      "5 MOUSE MOVE 12.5 40\n"
      "5 MOUSE left down\n"
      "7 RESIZE 400 300\n"
      "9 KEY F12 down\n"
      "11 wait reload\n",
      "s.txt");
  ASSERT_TRUE(s) << s.error().format();
  const auto& e = s->events;
  ASSERT_EQ(e.size(), 7u);
  EXPECT_EQ(e[6].event.type, InputEvent::Type::kWaitReload);
  EXPECT_EQ(e[0].frame, 2u);
  EXPECT_EQ(e[0].event.code, GLFW_KEY_ESCAPE);
  EXPECT_FALSE(e[0].event.down);
  EXPECT_EQ(e[1].event.type, InputEvent::Type::kMouseMove);  // same frame: file order kept
  EXPECT_DOUBLE_EQ(e[1].event.x, 12.5);
  EXPECT_EQ(e[2].event.type, InputEvent::Type::kMouseButton);
  EXPECT_EQ(e[2].event.code, GLFW_MOUSE_BUTTON_LEFT);
  EXPECT_EQ(e[3].event.type, InputEvent::Type::kResize);
  EXPECT_EQ(e[4].event.code, GLFW_KEY_F12);
  EXPECT_EQ(e[5].event.code, GLFW_KEY_W);
  EXPECT_TRUE(e[5].event.down);

  InputScript script = *s;
  EXPECT_EQ(script.take(1).size(), 0u);
  EXPECT_EQ(script.take(5).size(), 3u);  // frames 2 and 5
  EXPECT_EQ(script.take(5).size(), 0u);  // already taken
  EXPECT_EQ(script.take(100).size(), 4u);
}

TEST(InputScript, ErrorsNameFileAndLine) {
  struct Case {
    const char* text;
    const char* message;
  } cases[] = {
      {"x KEY W down\n", "s.txt:1: expected a frame number, got 'x'"},
      {"\n-1 KEY W down\n", "s.txt:2: expected a frame number, got '-1'"},
      {"1 KEY NOPE down\n", "s.txt:1: unknown key 'NOPE'"},
      {"1 KEY W sideways\n", "s.txt:1: expected down or up, got 'sideways'"},
      {"1 KEY W\n", "s.txt:1: expected 'FRAME KEY NAME down|up'"},
      {"1 MOUSE MOVE 1\n", "s.txt:1: expected 'FRAME MOUSE MOVE X Y' with X, Y in pixels"},
      {"1 MOUSE MOVE nan 1\n", "s.txt:1: expected 'FRAME MOUSE MOVE X Y' with X, Y in pixels"},
      {"1 MOUSE THUMB down\n", "s.txt:1: unknown mouse button 'THUMB'"},
      {"1 RESIZE 8 8\n", "s.txt:1: expected 'FRAME RESIZE W H' with whole W, H within [16, 16384] pixels"},
      {"1 JUMP\n", "s.txt:1: unknown event 'JUMP' (expected KEY, TEXT, MOUSE, RESIZE or WAIT)"},
      {"1\n", "s.txt:1: unknown event '' (expected KEY, TEXT, MOUSE, RESIZE or WAIT)"},
      {"1 WAIT\n", "s.txt:1: expected 'FRAME WAIT RELOAD'"},
      {"1 WAIT FOREVER\n", "s.txt:1: expected 'FRAME WAIT RELOAD'"},
  };
  for (const auto& c : cases) {
    auto s = parseInputScript(c.text, "s.txt");
    ASSERT_FALSE(s) << c.text;
    EXPECT_EQ(s.error().format(), c.message) << c.text;
  }
}

TEST(InputScript, KeyNames) {
  EXPECT_EQ(keyCodeFromName("a"), GLFW_KEY_A);
  EXPECT_EQ(keyCodeFromName("Z"), GLFW_KEY_Z);
  EXPECT_EQ(keyCodeFromName("7"), GLFW_KEY_7);
  EXPECT_EQ(keyCodeFromName("F1"), GLFW_KEY_F1);
  EXPECT_EQ(keyCodeFromName("f12"), GLFW_KEY_F12);
  EXPECT_EQ(keyCodeFromName("Esc"), GLFW_KEY_ESCAPE);
  EXPECT_EQ(keyCodeFromName("LEFT_SHIFT"), GLFW_KEY_LEFT_SHIFT);
  EXPECT_EQ(keyCodeFromName("F0"), -1);
  EXPECT_EQ(keyCodeFromName("F26"), -1);
  EXPECT_EQ(keyCodeFromName("AB"), -1);
  EXPECT_EQ(keyCodeFromName(""), -1);
}

TEST(FlyCamera, StartsAtThePoseAndSpeedScalesWithAltitude) {
  for (double h : {0.5, 10.0, 1000.0, 2.0e6}) {
    FlyCamera cam(GeodeticPose{20, 10, h, 0, 0, 0}, kR);
    EXPECT_NEAR(cam.altitude_m(), h, 1e-6 * (kR + h)) << h;
    EXPECT_NEAR(cam.latLon_deg().x, 20, 1e-9);
    EXPECT_NEAR(cam.latLon_deg().y, 10, 1e-9);
    // Altitude comes back from a planet-fixed position: ~1e-9 m of rounding at R = 6371 km.
    EXPECT_NEAR(cam.speed_mps(),
                std::clamp(h * FlyCamera::kSpeedPerAltitude, FlyCamera::kMinSpeed_mps, FlyCamera::kMaxSpeed_mps),
                1e-6 * FlyCamera::kSpeedPerAltitude * (1 + h * 1e-6));
  }
}

TEST(FlyCamera, ForwardMovesAlongTheView) {
  FlyCamera cam(GeodeticPose{0, 0, 1000, 0, 0, 0}, kR);  // looking north, level
  glm::dvec3 before = cam.position_m();
  FlyControls c;
  c.forward = 1;
  cam.update(c, 0.1);
  glm::dvec3 moved = cam.position_m() - before;
  EXPECT_NEAR(glm::length(moved), 100.0, 1e-6);  // 1000 m/s for 0.1 s
  EXPECT_GT(moved.z, 99.9);                      // north at (0, 0) is +z
}

TEST(FlyCamera, NeverBelowTheGround) {
  // Straight down at full boost for a long step, from several heights and places incl. the poles.
  for (double lat : {0.0, 45.0, 89.999, 90.0, -90.0}) {
    for (double h : {0.02, 1.0, 5000.0}) {
      FlyCamera cam(GeodeticPose{lat, 179.9, h, 30, -90, 0}, kR);
      FlyControls c;
      c.forward = 1;
      c.up = -1;
      c.boost = true;
      for (int i = 0; i < 50; ++i) cam.update(c, 1.0);
      // Keyboard flight stops at eye height, or at the height it started from when lower.
      EXPECT_GE(cam.altitude_m(), std::min(h, FlyCamera::kEyeHeight_m) - 1e-6) << lat << " " << h;
      EXPECT_LT(cam.altitude_m(), FlyCamera::kEyeHeight_m + 1e-6) << lat << " " << h;
      glm::dvec3 up = glm::normalize(cam.position_m());
      EXPECT_GE(glm::dot(cam.forward(), up), -std::sin(FlyCamera::kMaxPitch_deg * 3.14159265358979 / 180) - 1e-9);
    }
  }
}

TEST(FlyCamera, FollowsAGroundQuery) {
  // A ground 1 km above the reference sphere: the camera stops on it, not on the sphere.
  FlyCamera cam(GeodeticPose{10, 20, 500, 0, -90, 0}, kR, [](const glm::dvec3&) { return kR + 1000.0; });
  EXPECT_NEAR(cam.altitude_m(), 500, 1e-6);
  FlyControls c;
  c.up = -1;
  for (int i = 0; i < 100; ++i) cam.update(c, 1.0);
  EXPECT_NEAR(glm::length(cam.position_m()), kR + 1000.0 + FlyCamera::kEyeHeight_m, 1e-6);
  c.precise = true;  // Ctrl+Q goes on down to the engine's lowest camera
  for (int i = 0; i < 100; ++i) cam.update(c, 1.0);
  EXPECT_NEAR(glm::length(cam.position_m()), kR + 1000.0 + FlyCamera::kMinClearance_m, 1e-6);
}

TEST(FlyCamera, TurnsAndKeepsAnOrthonormalCamera) {
  FlyCamera cam(GeodeticPose{89.9999, 0, 100, 0, 0, 0}, kR);
  FlyControls c;
  c.turnRight_px = 200;
  c.turnUp_px = 5000;  // far past straight up: clamped
  cam.update(c, 0.016);
  Camera view = cam.camera(1.5);
  EXPECT_NEAR(glm::length(view.forward), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(view.right), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(view.up), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(view.forward, view.right), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(view.forward, view.up), 0.0, 1e-12);
  double pitch_deg = std::asin(glm::dot(view.forward, glm::normalize(cam.position_m()))) * 180 / 3.14159265358979;
  EXPECT_NEAR(pitch_deg, FlyCamera::kMaxPitch_deg, 1e-6);
  EXPECT_NEAR(view.near_m, 25.0, 1e-6);  // a quarter of the altitude
}

TEST(FlyCamera, GroundRadiusIsTheReferenceSphereForNow) {
  EXPECT_DOUBLE_EQ(groundRadiusBelow(glm::dvec3(0, 0, 1)), 6371000.0);
}

}  // namespace
}  // namespace globe
