#include "engine/viewer/viewer.h"

#include "engine/io/image_io.h"
#include "engine/render/render_output.h"
#include "engine/render/terrain_warnings.h"
#include "engine/viewer/fly_camera.h"
#include "engine/viewer/frame_time_log.h"
#include "engine/viewer/overlay.h"
#include "engine/viewer/path_recorder.h"
#include "engine/viewer/swapchain.h"
#include "engine/viewer/viewer_bodies.h"
#include "engine/viewer/window.h"
#include "engine/vk/deferred_release_queue.h"
#include "engine/vk/frame_ring.h"
#include "engine/vk/offscreen_target.h"
#include "engine/vk/vk_check.h"
#include "planet/analysis/frame_stats.h"
#include "planet/camera/camera_orientation.h"
#include "planet/camera/camera_path_file.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <unordered_set>

namespace globe {

namespace {

// The viewer indexes the terrain's per-frame buffers with its FrameRing slot. Two constants until
// TerrainRenderer takes vk::kFramesInFlight: they must agree.

constexpr double kFixedStep_s = 1.0 / 60.0;
constexpr float kSpaceColour[4] = {0.0f, 0.0f, 0.0f, 1.0f};
constexpr int kMaxReloadWait_s = 60;  // a script's WAIT RELOAD gives up after this

// Keyboard and mouse state built from the event stream (window and script alike).
struct InputState {
  std::unordered_set<int> keysDown;
  bool dragging = false;  // left button held
  bool haveCursor = false;
  double cursorX = 0, cursorY = 0;
  double dragX_px = 0, dragY_px = 0;  // accumulated this frame

  bool down(int key) const { return keysDown.count(key) != 0; }
  double axis(int positive, int negative) const { return (down(positive) ? 1.0 : 0.0) - (down(negative) ? 1.0 : 0.0); }
};

// Lines on stdout are how scripted runs (tests) follow the viewer: flush each one.
void printLine(const std::string& line) {
  std::fputs((line + "\n").c_str(), stdout);
  std::fflush(stdout);
}

std::unique_ptr<ViewerScene> makeScene(vk::Device& device, ViewerSceneOptions options) {
  auto scene = ViewerScene::create(device, std::move(options));
  // The command validated the settings and the planet; what is left is a device failure.
  if (!scene) throw std::runtime_error(scene.error().format());
  return std::move(*scene);
}

// The scene target's anti-aliasing: the terrain's (the sphere mode's passes draw one sample per pixel).
vk::Antialiasing sceneAntialiasing(const ViewerSceneOptions& scene) {
  return scene.mode == ViewerMode::kTerrain ? scene.terrain.antialiasing : vk::Antialiasing::kNone;
}

}  // namespace

using Clock = std::chrono::steady_clock;

struct Viewer::State {
  State(Window& w, vk::Device& d, ViewerOptions o)
      : window(w),
        device(d),
        options(std::move(o)),
        swapchain(d, w.framebufferExtent(), options.vsync),
        ring(d),
        target(std::make_unique<vk::OffscreenTarget>(d, swapchain.extent(), sceneAntialiasing(options.scene))),
        scene(makeScene(d, options.scene)),
        overlay(std::make_unique<Overlay>(d, w, swapchain)),
        // The scene outlives the camera (declared earlier), and is never replaced: a reload
        // swaps the planet inside it, so this query always sees the current ground.
        camera(
            options.pose, scene->radius_m(), [this](const glm::dvec3& dir) { return scene->groundRadius(dir); },
            [this](const glm::dvec3& from, const glm::dvec3& to) {
              return scene->guardedCameraMove(from, to, FlyCamera::kMinClearance_m);
            },
            scene->shape()) {}

  void handle(const InputEvent& e);
  bool recreateSwapchain();
  void renderFrame(uint32_t image, VkCommandBuffer cmd, const Camera& cam);
  Status saveScreenshot(const std::string& path, const Camera& cam);
  void reportReload(const ReloadOutcome& outcome);
  void reportTerrainWarnings();
  GeodeticPose currentPose(const Camera& cam) const;
  void toggleRecording(const Camera& cam);
  void stopRecording();
  void waitForReload();
  Camera frameCamera(double step_s, Clock::time_point now);
  void describeCamera(OverlayView& view, const Camera& cam) const;
  void logFrame(Clock::time_point runStart);
  Status writeFrameTimes() const;
  bool processInput();  // false: quit
  Camera stepCamera(double wall_s, Clock::time_point now);
  void buildOverlay(double wall_s, const Camera& cam);
  void stepBodies(double step_s, const Camera& cam);
  void takeRequestedScreenshot(const Camera& cam);

  Window& window;
  vk::Device& device;
  ViewerOptions options;
  vk::DeferredReleaseQueue releases;  // destroyed after everything below that it may hold
  vk::Swapchain swapchain;
  vk::FrameRing ring;
  std::unique_ptr<vk::OffscreenTarget> target;  // swapchain-sized display-encoded colour + reversed-Z depth
  std::unique_ptr<ViewerScene> scene;
  std::unique_ptr<Overlay> overlay;
  FlyCamera camera;
  PathRecorder recorder;

  InputState input;
  uint64_t frame = 0;  // frames submitted so far = number of the next frame
  bool quit = false;
  bool screenshotRequested = false;
  bool recordToggleRequested = false;
  bool dropRequested = false;
  glm::dvec2 sunMove{0.0};               // H/K: azimuth, U/J: elevation (degrees) asked since the last frame
  std::unique_ptr<ViewerBodies> bodies;  // created by the first drop (B); reset on planet reload
  bool waitForReloadRequested = false;
  bool swapchainStale = false;
  std::string message;                    // shown in the overlay
  TerrainWarnings terrainWarnings;        // budgets reached, generation failures: once each
  std::vector<std::string> planetErrors;  // of the planet file on disk, while it is invalid
  FrameStats stats;
  FrameTimeLog frameTimes;
  Clock::time_point lastPresent;                    // when the previous frame was presented
  std::optional<Clock::time_point> pathClockStart;  // path mode: when frame 0 was presented
  double pathTime_s = 0;                            // path time of the current frame
  bool pathEnded = false;                           // the current frame shows the path's end
};

Camera Viewer::State::frameCamera(double step_s, Clock::time_point now) {
  const VkExtent2D extent = target->extent();
  const double aspect = double(extent.width) / double(extent.height);
  if (options.path) {
    // Frame 0 shows the start; then the wall clock drives the path (the warm-up before frame 0
    // does not count), or 1/60 s per frame for deterministic runs.
    const CameraPath& path = *options.path;
    if (frame == 0 || !pathClockStart) {
      pathTime_s = path.startTime_s();
    } else if (options.fixedStep) {
      pathTime_s += kFixedStep_s;
    } else {
      pathTime_s = path.startTime_s() + std::chrono::duration<double>(now - *pathClockStart).count();
    }
    pathEnded = pathTime_s >= path.endTime_s();
    pathTime_s = std::min(pathTime_s, path.endTime_s());
    return path.cameraAt(
        pathTime_s, scene->radius_m(), aspect, [this](const glm::dvec3& dir) { return scene->groundRadius(dir); },
        scene->shape());
  }
  // Keys move, left-drag turns.
  FlyControls controls;
  controls.forward = input.axis(GLFW_KEY_W, GLFW_KEY_S);
  controls.right = input.axis(GLFW_KEY_D, GLFW_KEY_A);
  controls.up = input.axis(GLFW_KEY_E, GLFW_KEY_Q);
  controls.boost = input.down(GLFW_KEY_LEFT_SHIFT) || input.down(GLFW_KEY_RIGHT_SHIFT);
  controls.turnRight_px = input.dragX_px;
  controls.turnUp_px = -input.dragY_px;
  input.dragX_px = input.dragY_px = 0;
  camera.update(controls, step_s);
  return camera.camera(aspect);
}

void Viewer::State::describeCamera(OverlayView& view, const Camera& cam) const {
  const GeodeticPose pose = currentPose(cam);
  view.altitude_m = options.path ? pose.height_m : camera.altitude_m();
  view.latitude_deg = pose.latitude_deg;
  view.longitude_deg = pose.longitude_deg;
  view.speed_mps = camera.speed_mps();
}

void Viewer::State::logFrame(Clock::time_point runStart) {
  const Clock::time_point now = Clock::now();
  const double frame_ms = std::chrono::duration<double, std::milli>(now - lastPresent).count();
  lastPresent = now;
  if (options.path && !pathClockStart) pathClockStart = now;
  frameTimes.add(std::chrono::duration<double>(now - runStart).count(), options.path ? pathTime_s : 0.0, frame_ms,
                 stats);
}

Status Viewer::State::writeFrameTimes() const {
  printLine(frameTimes.summaryLine());
  if (options.frameTimesPath.empty()) return Ok{};
  return frameTimes.write(options.frameTimesPath);
}

void Viewer::State::handle(const InputEvent& e) {
  switch (e.type) {
    case InputEvent::Type::kKey:
      if (e.down) {
        input.keysDown.insert(e.code);
        if (e.code == GLFW_KEY_ESCAPE) quit = true;
        if (e.code == GLFW_KEY_F12 || e.code == GLFW_KEY_P) screenshotRequested = true;
        if (e.code == GLFW_KEY_F1 || e.code == GLFW_KEY_L) scene->cycleDebugView();
        if (e.code == GLFW_KEY_R) recordToggleRequested = true;
        if (e.code == GLFW_KEY_B) dropRequested = true;
        if (e.code == GLFW_KEY_H || e.code == GLFW_KEY_K) sunMove.x += e.code == GLFW_KEY_K ? 15.0 : -15.0;
        if (e.code == GLFW_KEY_U || e.code == GLFW_KEY_J) sunMove.y += e.code == GLFW_KEY_U ? 5.0 : -5.0;
      } else {
        input.keysDown.erase(e.code);
      }
      break;
    case InputEvent::Type::kMouseButton:
      if (e.code == GLFW_MOUSE_BUTTON_LEFT)
        input.dragging = e.down && !overlay->wantsMouse();  // drags on the overlay are its own
      break;
    case InputEvent::Type::kMouseMove:
      if (input.haveCursor && input.dragging) {
        input.dragX_px += e.x - input.cursorX;
        input.dragY_px += e.y - input.cursorY;
      }
      input.cursorX = e.x;
      input.cursorY = e.y;
      input.haveCursor = true;
      break;
    case InputEvent::Type::kResize:
      window.setSize(uint32_t(e.x), uint32_t(e.y));
      break;
    case InputEvent::Type::kWaitReload:
      waitForReloadRequested = true;
      break;
  }
}

void Viewer::State::waitForReload() {
  // Scripts only: a test edits the planet file while the loop stands still, so the frame numbers
  // of its screenshots do not depend on how fast this machine renders.
  printLine("waiting for the planet file to change (frame " + std::to_string(frame) + ")");
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

bool Viewer::State::recreateSwapchain() {
  VkExtent2D extent = window.framebufferExtent();
  if (extent.width == 0 || extent.height == 0) return false;  // minimised: nothing to present to
  // Everything below may still be in use by frames up to frame - 1; `frame` is the conservative key.
  overlay->retireFramebuffers(releases, frame);
  swapchain.recreate(extent, releases, frame);
  overlay->attach(swapchain);
  VkExtent2D size = swapchain.extent();
  if (size.width != target->extent().width || size.height != target->extent().height) {
    const vk::Antialiasing aa = target->antialiasing();
    releases.retire(frame, std::move(target));
    target = std::make_unique<vk::OffscreenTarget>(device, size, aa);
    scene->setViewHeight(double(size.height));
  }
  swapchainStale = false;
  return true;
}

void Viewer::State::renderFrame(uint32_t image, VkCommandBuffer cmd, const Camera& cam) {
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  GLOBE_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));

  // Scene: display-encoded colour and reversed-Z depth. The terrain's per-frame buffers are indexed by
  // frame % kFramesInFlight, the FrameRing slot whose fence begin() waited for.
  scene->prepare(cmd, cam, uint32_t(frame % vk::kFramesInFlight));
  target->begin(cmd, kSpaceColour);
  scene->record(cmd, cam, uint32_t(frame % vk::kFramesInFlight));
  target->end(cmd);  // colour is now TRANSFER_SRC_OPTIMAL

  // Copy into the swapchain image (same 8-bit encoding; a blit also converts other formats).
  VkImage swapImage = swapchain.image(image);
  vk::transitionImage(cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  VkExtent2D e = target->extent();
  VkImageBlit blit{};
  blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {int32_t(e.width), int32_t(e.height), 1};
  blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.dstOffsets[1] = blit.srcOffsets[1];
  vkCmdBlitImage(cmd, target->colour().handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, swapImage,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);
  vk::transitionImage(cmd, swapImage, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  overlay->record(cmd, image);  // leaves the image in PRESENT_SRC_KHR
  GLOBE_VK_CHECK(vkEndCommandBuffer(cmd));
}

Status Viewer::State::saveScreenshot(const std::string& path, const Camera& cam) {
  // The last submitted frame must be complete before its target is read; screenshots are rare.
  GLOBE_VK_CHECK(vkQueueWaitIdle(device.queue()));
  vk::ReadbackImage frameImage = target->readback();
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
      printLine("planet reloaded: " + file + when);
    } else if (outcome.buildingTables) {
      message = "building the new planet's atmosphere tables (once; ~20 s on a CPU)";
      printLine("planet changed: " + file + when + "; building its atmosphere tables, the last planet stays meanwhile");
    } else {
      printLine("planet unchanged: " + file + when);
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
  printLine("planet reload failed: " + file + when);
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
  printLine("recording path (frame " + std::to_string(frame) + ")");
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
  printLine("path " + file + text + " (frame " + std::to_string(frame) + ")");
}

Viewer::Viewer(Window& window, vk::Device& device, ViewerOptions options)
    : s_(std::make_unique<State>(window, device, std::move(options))) {}

Viewer::~Viewer() {
  // Nothing may be destroyed while the GPU still uses it; a failed wait leaves nothing to wait for.
  (void)vkDeviceWaitIdle(s_->device.device());
}

uint64_t Viewer::framesRendered() const { return s_->frame; }

// Input: the window's events, then the script's for this frame.
bool Viewer::State::processInput() {
  for (const InputEvent& e : window.pollEvents()) handle(e);
  for (const InputEvent& e : options.script.take(frame)) handle(e);
  if (waitForReloadRequested) {
    waitForReloadRequested = false;
    waitForReload();
  }
  if (window.shouldClose()) quit = true;
  return !quit;
}

// The frame's camera (the path's, or the fly camera's), and path recording in camera time: what
// the camera advanced by is what the replay advances by. `wall_s` is the real time since the last frame.
Camera Viewer::State::stepCamera(double wall_s, Clock::time_point now) {
  const double step_s = options.fixedStep ? kFixedStep_s : std::min(wall_s, 0.25);
  Camera cam = frameCamera(step_s, now);
  if (recordToggleRequested) {
    recordToggleRequested = false;
    toggleRecording(cam);
  } else if (recorder.recording()) {
    recorder.advance(step_s, currentPose(cam));
  }
  stepBodies(step_s, cam);
  if (sunMove != glm::dvec2(0.0)) {
    scene->moveSun(cam.position_m, sunMove.x, sunMove.y);
    const SunAngles sun = sunAnglesAt(cam.position_m, scene->sunDirection());
    message = "sun at azimuth " + std::to_string(int(std::lround(sun.azimuth_deg))) + ", elevation " +
              std::to_string(int(std::lround(sun.elevation_deg))) + " degrees";
    sunMove = glm::dvec2(0.0);
  }
  return cam;
}

// B: a body where the view ray meets the ground; then every frame the bodies advance.
void Viewer::State::stepBodies(double step_s, const Camera& cam) {
  if (dropRequested && scene->mode() == ViewerMode::kTerrain) {
    if (!bodies)
      bodies = std::make_unique<ViewerBodies>(device, scene->terrain()->model(), scene->planet().surface_gravity_m_s2,
                                              scene->terrain()->settings().gridCells);
    message = bodies->dropWhereLooking(cam) ? "dropped body " + std::to_string(bodies->count())
                                            : "no ground within 100 km along the view";
  }
  dropRequested = false;
  if (bodies) bodies->advance(step_s);
}

void Viewer::State::buildOverlay(double wall_s, const Camera& cam) {
  OverlayView view;
  view.stats = stats;  // the previous frame's complete statistics (draws are counted in record)
  view.stats.frame_ms = wall_s * 1000.0;
  describeCamera(view, cam);
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
    printLine("screenshot " + path + (scene->converged() ? " (converged)" : " (streaming)"));
  } else {
    message = st.error().format();
    std::fprintf(stderr, "globe: warning: %s\n", message.c_str());
  }
}

Status Viewer::run() {
  State& s = *s_;
  Clock::time_point previous = Clock::now();
  const Clock::time_point runStart = previous;
  s.lastPresent = previous;
  Camera lastCamera = s.camera.camera(double(s.target->extent().width) / s.target->extent().height);

  while (!s.quit && !(s.options.frames && s.frame >= s.options.frames)) {
    if (!s.processInput()) break;
    Clock::time_point now = Clock::now();
    double wall_s = std::chrono::duration<double>(now - previous).count();
    previous = now;

    // Live reload, before this frame uses the terrain (a reload may replace it).
    if (auto outcome = s.scene->pollReload(now)) s.reportReload(*outcome);

    vk::FrameRing::Slot slot = s.ring.begin(s.frame);
    if (s.frame >= vk::kFramesInFlight) s.releases.collect(s.frame - vk::kFramesInFlight);
    if (s.window.takeResized() || s.swapchainStale) {
      if (!s.recreateSwapchain()) {
        glfwWaitEventsTimeout(0.05);  // minimised: sleep until something changes
        continue;
      }
    }
    std::optional<uint32_t> image = s.swapchain.acquire(slot.imageAcquired);
    if (!image) {  // out of date: rebuild and try again next iteration
      s.swapchainStale = true;
      continue;
    }
    Camera cam = s.stepCamera(wall_s, now);
    // FrameRing::begin waited for frame - kFramesInFlight. The terrain counts frames from
    // kFramesInFlight, so its completed frame (its own numbering) is `s.frame` and never underflows:
    // terrain frames below kFramesInFlight never existed, so nothing they "used" can be in flight.
    s.scene->update(s.frame + vk::kFramesInFlight, cam, s.frame);
    s.reportTerrainWarnings();
    s.buildOverlay(wall_s, cam);

    s.renderFrame(*image, slot.cmd, cam);
    s.stats = s.scene->stats();
    s.ring.submit(s.frame, s.swapchain.renderFinished(*image));
    if (!s.swapchain.present(*image)) s.swapchainStale = true;
    lastCamera = cam;
    s.logFrame(runStart);
    ++s.frame;
    if (s.pathEnded && !s.options.holdAtPathEnd) s.quit = true;  // the path's end is drawn
    s.takeRequestedScreenshot(cam);
  }

  // Quitting while recording keeps the flight.
  if (s.recorder.recording()) s.stopRecording();
  GLOBE_VK_CHECK(vkDeviceWaitIdle(s.device.device()));
  s.releases.releaseAll();
  if (Status st = s.writeFrameTimes(); !st) return st;
  if (!s.options.screenshotPath.empty()) {
    if (s.frame == 0) return Error::inField("--screenshot", "no frame was rendered");
    return s.saveScreenshot(s.options.screenshotPath, lastCamera);
  }
  return Ok{};
}

}  // namespace globe
