// CPU parts of the viewer's path recording and live reload: the recorder's keyframe spacing and
// the round trip of a recorded camera through a path file (what `globe bench --path` replays), and
// the planet file watcher's change detection.
#include "engine/viewer/fly_camera.h"
#include "engine/viewer/path_recorder.h"
#include "engine/viewer/planet_file_watcher.h"
#include "planet/camera/camera_orientation.h"
#include "planet/paths/camera_path_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace globe {
namespace {

constexpr double kR = 6371000.0;

double groundBelow(const glm::dvec3& dir) {  // a bumpy ground, so heights are not trivial
  return kR + 300.0 * dir.x + 120.0 * dir.z;
}

TEST(PathRecorder, KeyframesEveryIntervalAndAtTheStop) {
  PathRecorder r;
  GeodeticPose pose{20, 10, 5000, 30, -10, 0};
  r.start(pose);
  EXPECT_TRUE(r.recording());
  for (int i = 1; i <= 70; ++i) {  // 70 frames of 1/60 s: keyframes at 0, 0.25, 0.5, 0.75 ... then the stop
    pose.longitude_deg += 1e-4;
    r.advance(1.0 / 60.0, pose);
  }
  auto path = r.stop();
  ASSERT_TRUE(path) << path.error().format();
  EXPECT_FALSE(r.recording());
  const auto& k = path->keyframes();
  ASSERT_EQ(k.size(), 6u);  // 0, 15, 30, 45, 60 frames and 70 (the stop)
  EXPECT_DOUBLE_EQ(k[0].time_s, 0.0);
  EXPECT_NEAR(k[1].time_s, 0.25, 1e-12);
  EXPECT_NEAR(k.back().time_s, 70.0 / 60.0, 1e-12);
  EXPECT_DOUBLE_EQ(k.back().pose.longitude_deg, pose.longitude_deg);
}

TEST(PathRecorder, FastTurnsGetExtraKeyframes) {
  PathRecorder r;
  GeodeticPose pose{0, 0, 100, 0, 0, 0};
  r.start(pose);
  for (int i = 1; i <= 10; ++i) {  // 10 frames turning 20 degrees each: 200 degrees in 1/6 s
    pose.heading_deg += 20;
    if (pose.heading_deg > 180) pose.heading_deg -= 360;
    r.advance(1.0 / 60.0, pose);
  }
  auto path = r.stop();  // would be an invalid path (turn > 179 degrees) without the extra keyframes
  ASSERT_TRUE(path) << path.error().format();
  EXPECT_GE(path->keyframes().size(), 4u);
}

TEST(PathRecorder, TooShortIsAnError) {
  PathRecorder r;
  r.start(GeodeticPose{0, 0, 100, 0, 0, 0});
  auto path = r.stop();
  ASSERT_FALSE(path);
  EXPECT_NE(path.error().format().find("too short"), std::string::npos);
}

TEST(PathRecorder, RecordedCameraReplaysThroughAPathFile) {
  // Fly, record poses as the viewer does, write and read the file, and compare the replayed
  // camera at each keyframe with the flown one.
  FlyCamera fly(GeodeticPose{46.5, 7.9, 3000, 120, -10, 0}, kR, groundBelow);
  PathRecorder r;
  auto poseOf = [&](const Camera& c) { return poseFromCamera(c, groundBelow(glm::normalize(c.position_m))); };
  r.start(poseOf(fly.camera(1.5)));
  std::vector<Camera> flown{fly.camera(1.5)};
  for (int i = 1; i <= 120; ++i) {
    FlyControls c;
    c.forward = 1;
    c.turnRight_px = i < 60 ? 3 : -2;
    c.up = i > 90 ? -1 : 0;
    fly.update(c, 1.0 / 60.0);
    r.advance(1.0 / 60.0, poseOf(fly.camera(1.5)));
    if (i % 15 == 0) flown.push_back(fly.camera(1.5));
  }
  auto path = r.stop();
  ASSERT_TRUE(path) << path.error().format();
  auto back = parseCameraPath(formatCameraPath(*path), "rec.path");
  ASSERT_TRUE(back) << back.error().format();
  ASSERT_EQ(back->keyframes().size(), flown.size());  // 0, 15, ..., 120: the stop falls on a keyframe time
  for (size_t k = 0; k < flown.size(); ++k) {
    Camera replay = back->cameraAt(back->keyframes()[k].time_s, kR, 1.5, groundBelow);
    EXPECT_LT(glm::length(replay.position_m - flown[k].position_m), 1e-6) << k;
    EXPECT_GT(glm::dot(replay.forward, flown[k].forward), 1 - 1e-12) << k;
    EXPECT_GT(glm::dot(replay.up, flown[k].up), 1 - 1e-12) << k;
  }
}

TEST(PlanetFileWatcher, ReportsEachChangeOnce) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("globe_watcher_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string file = (dir / "p.toml").string();
  std::ofstream(file) << "a";
  using Clock = PlanetFileWatcher::Clock;
  PlanetFileWatcher w(file, std::chrono::milliseconds(100));
  Clock::time_point t = Clock::now() + std::chrono::seconds(1);
  EXPECT_FALSE(w.changed(t));                                  // nothing changed since construction
  std::ofstream(file) << "abc";                                // size changes even if the mtime does not
  EXPECT_FALSE(w.changed(t + std::chrono::milliseconds(10)));  // not yet due
  EXPECT_TRUE(w.changed(t + std::chrono::milliseconds(200)));
  EXPECT_FALSE(w.changed(t + std::chrono::milliseconds(400)));  // reported once
  fs::remove(file);
  EXPECT_TRUE(w.changed(t + std::chrono::milliseconds(600)));  // gone is a change too
  std::ofstream(file + ".tmp") << "replaced";
  fs::rename(file + ".tmp", file);  // an editor's atomic save
  EXPECT_TRUE(w.changed(t + std::chrono::milliseconds(800)));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace globe
