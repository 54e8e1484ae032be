#include "engine/viewer/viewer_state.h"
#include "engine/io/image_io.h"
#include "engine/render/render_output.h"
#include "engine/vk/vk_check.h"
#include "planet/camera/camera_orientation.h"
#include "planet/paths/camera_path_file.h"

#include <cstdio>
#include <filesystem>
#include <thread>

namespace globe {

namespace {
constexpr int kMaxReloadWait_s = 60;  // a script's WAIT RELOAD gives up after this
}  // namespace

void printViewerLine(const std::string& line) {
  std::fputs((line + "\n").c_str(), stdout);
  std::fflush(stdout);
}

// G's line or a bookmark key: the fly camera jumps there. What happened is also a line on stdout.
void Viewer::State::goToAskedPlace(double aspect) {
  if (!places.pending()) return;
  if (auto pose = places.apply(currentPose(camera.camera(aspect)), message)) camera.moveTo(*pose);
  printViewerLine(message + " (frame " + std::to_string(frame) + ")");
}

void Viewer::State::describeCamera(OverlayView& view) const {
  const GeodeticPose& pose = framePose;
  view.altitude_m = options.path ? pose.height_m : camera.altitude_m();
  view.latitude_deg = pose.latitude_deg;
  view.longitude_deg = pose.longitude_deg;
  view.heading_deg = pose.heading_deg;
  view.pitch_deg = pose.pitch_deg;
  view.speed_mps = camera.speed_mps();
  if (!options.path && camera.overSea() && view.altitude_m < 1000.0)
    view.hint = "open sea below: E climbs, G goes to a place, F2 shows the keys";
  view.help = help;
  view.typing = places.typing();
  view.typed = places.typed();
  view.bookmarksPath = places.bookmarksPath();
  for (std::size_t i = 0; i < places.bookmarks().size(); ++i) {
    const Bookmark& b = places.bookmarks()[i];
    char text[160];
    std::snprintf(text, sizeof text, "%zu  %.4f, %.4f, %.0f m  ", i + 1, b.pose.latitude_deg, b.pose.longitude_deg,
                  b.pose.height_m);
    view.bookmarks.push_back(text + b.name);
  }
}

void Viewer::State::logFrame(Clock::time_point runStart) {
  const Clock::time_point now = Clock::now();
  const double frame_ms = std::chrono::duration<double, std::milli>(now - lastPresent).count();
  lastPresent = now;
  if (options.path && !pathClockStart) pathClockStart = now;
  frameTimes.add(std::chrono::duration<double>(now - runStart).count(), options.path ? pathTime_s : 0.0, frame_ms,
                 stats, framePose);
}

Status Viewer::State::writeFrameTimes() const {
  printViewerLine(frameTimes.summaryLine());
  if (options.frameTimesPath.empty()) return Ok{};
  return frameTimes.write(options.frameTimesPath);
}

void Viewer::State::waitForReload() {
  // Scripts only: a test edits the planet file while the loop stands still, so the frame numbers
  // of its screenshots do not depend on how fast this machine renders.
  printViewerLine("waiting for the planet file to change (frame " + std::to_string(frame) + ")");
  Clock::time_point deadline = Clock::now() + std::chrono::seconds(kMaxReloadWait_s);
  while (Clock::now() < deadline && !quit) {
    for (const InputEvent& e : window.pollEvents()) handle(e);
    if (auto outcome = scene->pollReload(Clock::now())) {
      reportReload(*outcome);
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::fprintf(stderr, "globe: warning: the planet file did not change within %d s; going on\n", kMaxReloadWait_s);
}

Status Viewer::State::saveScreenshot(const std::string& path, const Camera& cam) {
  // The last submitted frame must be complete before its target is read; screenshots are rare.
  GLOBE_VK_CHECK(vkQueueWaitIdle(device.queue()));
  ReadbackImage frameImage = target->readback();
  ImageRgba image = toImage(frameImage, cam);
  return writeImage(path, image, "screenshot");
}

// The terrain's degradations (a frame budget reached, ...), once each, on stderr and on screen.
void Viewer::State::reportTerrainWarnings() {
  if (const Terrain* t = scene->terrain()) {
    for (const std::string& warning : terrainWarnings.takeNew(*t)) {
      message = warning;
      std::fprintf(stderr, "globe: warning: %s\n", warning.c_str());
    }
  }
}

void Viewer::State::reportReload(const ReloadOutcome& outcome) {
  const std::string& file = scene->planetPath();
  std::string when = " (frame " + std::to_string(frame) + ")";
  if (outcome.errors.empty()) {
    planetErrors.clear();
    if (outcome.reloaded) {
      bodies.reset();  // they live on the old planet's meshes
      terrainWarnings.reset();
      message = "reloaded " + file;
      printViewerLine("planet reloaded: " + file + when);
    } else if (outcome.buildingTables) {
      message = "building the new planet's atmosphere tables (once; ~20 s on a CPU)";
      printViewerLine("planet changed: " + file + when +
                      "; building its atmosphere tables, the last planet stays meanwhile");
    } else {
      printViewerLine("planet unchanged: " + file + when);
    }
    return;
  }
  // Once per change of the file: the overlay keeps showing them until the next valid save.
  planetErrors.clear();
  std::fprintf(stderr, "globe: warning: %s is invalid (%zu error(s)); keeping the last good planet\n", file.c_str(),
               outcome.errors.size());
  for (const Error& e : outcome.errors) {
    planetErrors.push_back(e.format());
    std::fprintf(stderr, "globe: error: %s\n", planetErrors.back().c_str());
  }
  std::fflush(stderr);
  printViewerLine("planet reload failed: " + file + when);
}

GeodeticPose Viewer::State::currentPose(const Camera& cam) const {
  return poseFromCamera(cam, scene->groundRadius(scene->normalBelow(cam.position_m)), scene->shape());
}

void Viewer::State::toggleRecording(const Camera& cam) {
  if (recorder.recording()) {
    stopRecording();
    return;
  }
  recorder.start(currentPose(cam));
  printViewerLine("recording path (frame " + std::to_string(frame) + ")");
}

void Viewer::State::stopRecording() {
  auto path = recorder.stop();
  if (!path) {
    message = "path not saved: " + path.error().format();
    std::fprintf(stderr, "globe: warning: %s\n", message.c_str());
    return;
  }
  std::string file = options.recordFile.empty() ? timestampedPathFile(options.recordDirectory) : options.recordFile;
  if (Status st = saveCameraPath(file, *path); !st) {
    message = "path not saved: " + st.error().format();
    std::fprintf(stderr, "globe: warning: %s\n", message.c_str());
    return;
  }
  char text[96];
  std::snprintf(text, sizeof text, " (%zu keyframes, %.2f s)", path->keyframes().size(), path->duration_s());
  message = "saved path " + file + text;
  printViewerLine("path " + file + text + " (frame " + std::to_string(frame) + ")");
}

void Viewer::State::buildOverlay(double wall_s, const Camera& cam) {
  OverlayView view;
  view.stats = stats;  // the previous frame's complete statistics (draws are counted in record)
  view.stats.frame_ms = wall_s * 1000.0;
  describeCamera(view);
  view.debugView = scene->debugViewName();
  view.deviceName = device.name();
  view.planet = scene->planet().name + " (" + scene->planetPath() + ")";
  if (recorder.recording()) {
    char text[96];
    std::snprintf(text, sizeof text, "recording... %.1f s, %zu keyframes (R stops)", recorder.elapsed_s(),
                  recorder.keyframeCount());
    view.recording = text;
  }
  view.message = message;
  view.errors = planetErrors;
  if (bodies) view.bodies = bodies->discs(cam, double(target->extent().width), double(target->extent().height));
  overlay->build(view);
}

// F12/P: the frame just submitted, named by its number.
void Viewer::State::takeRequestedScreenshot(const Camera& cam) {
  if (!screenshotRequested) return;
  screenshotRequested = false;
  char name[64];
  std::snprintf(name, sizeof name, "globe-frame%06llu%s", static_cast<unsigned long long>(frame - 1),
                options.screenshotExtension.c_str());
  std::string path = (std::filesystem::path(options.screenshotDirectory) / name).string();
  if (Status st = saveScreenshot(path, cam); st) {
    message = "saved " + path;
    // Tests compare screenshots of still views: say whether the terrain had converged.
    printViewerLine("screenshot " + path + (scene->converged() ? " (converged)" : " (streaming)"));
  } else {
    message = st.error().format();
    std::fprintf(stderr, "globe: warning: %s\n", message.c_str());
  }
}

}  // namespace globe
