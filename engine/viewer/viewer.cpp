#include "engine/viewer/viewer.h"

#include "engine/viewer/viewer_state.h"
#include "engine/vk/vk_check.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>

namespace globe {

namespace {

constexpr float kSpaceColour[4] = {0.0f, 0.0f, 0.0f, 1.0f};

std::unique_ptr<ViewerScene> makeScene(vk::Device& device, ViewerSceneOptions options) {
  auto scene = ViewerScene::create(device, std::move(options));
  // The command validated the settings and the planet; what is left is a device failure.
  if (!scene) throw std::runtime_error(scene.error().format());
  return std::move(*scene);
}

// The scene target's anti-aliasing: the terrain's (the sphere mode's passes draw one sample per pixel).
Antialiasing sceneAntialiasing(const ViewerSceneOptions& scene) {
  return scene.mode == ViewerMode::kTerrain ? scene.terrain.antialiasing : Antialiasing::kNone;
}

}  // namespace

Viewer::State::State(Window& w, vk::Device& d, ViewerOptions o)
    : window(w),
      device(d),
      options(std::move(o)),
      swapchain(d, w.framebufferExtent(), options.vsync),
      ring(d),
      target(std::make_unique<OffscreenTarget>(d, swapchain.extent(), sceneAntialiasing(options.scene))),
      scene(makeScene(d, options.scene)),
      overlay(std::make_unique<Overlay>(d, w, swapchain)),
      // The scene outlives the camera (declared earlier), and is never replaced: a reload
      // swaps the planet inside it, so this query always sees the current ground.
      camera(
          options.pose, scene->radius_m(), [this](const glm::dvec3& dir) { return scene->groundRadius(dir); },
          [this](const glm::dvec3& from, const glm::dvec3& to, double clearance_m) {
            return scene->guardedCameraMove(from, to, clearance_m);
          },
          scene->shape()),
      gpuTimer(d),
      places(options.bookmarksPath, options.bookmarks) {
  camera.setSeaQuery([this](const glm::dvec3& dir) { return scene->seaBelow(dir); });
}

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
      pathTime_s += kViewerFixedStep_s;
    } else {
      pathTime_s = path.startTime_s() + std::chrono::duration<double>(now - *pathClockStart).count();
    }
    pathEnded = pathTime_s >= path.endTime_s();
    pathTime_s = std::min(pathTime_s, path.endTime_s());
    return path.cameraAt(
        pathTime_s, scene->radius_m(), aspect, [this](const glm::dvec3& dir) { return scene->groundRadius(dir); },
        scene->shape());
  }
  goToAskedPlace(aspect);
  // Keys move, left-drag turns.
  FlyControls controls;
  controls.forward = input.axis(GLFW_KEY_W, GLFW_KEY_S);
  controls.right = input.axis(GLFW_KEY_D, GLFW_KEY_A);
  controls.up = input.axis(GLFW_KEY_E, GLFW_KEY_Q);
  controls.boost = input.down(GLFW_KEY_LEFT_SHIFT) || input.down(GLFW_KEY_RIGHT_SHIFT);
  controls.precise = input.down(GLFW_KEY_LEFT_CONTROL) || input.down(GLFW_KEY_RIGHT_CONTROL);
  controls.turnRight_px = input.dragX_px;
  controls.turnUp_px = -input.dragY_px;
  input.dragX_px = input.dragY_px = 0;
  camera.update(controls, step_s);
  return camera.camera(aspect);
}

void Viewer::State::handle(const InputEvent& e) {
  if (!options.path && places.handle(e)) return;  // G, M, 1-9, and everything typed on the go-to line
  switch (e.type) {
    case InputEvent::Type::kKey:
      if (e.down) {
        input.keysDown.insert(e.code);
        if (e.code == GLFW_KEY_ESCAPE) quit = true;
        if (e.code == GLFW_KEY_F12 || e.code == GLFW_KEY_P) screenshotRequested = true;
        if (e.code == GLFW_KEY_F1 || e.code == GLFW_KEY_L) scene->cycleDebugView();
        if (e.code == GLFW_KEY_F2 || e.code == GLFW_KEY_I) help = !help;
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
    case InputEvent::Type::kChar:  // typing is for the go-to line only
      break;
  }
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
    const Antialiasing aa = target->antialiasing();
    releases.retire(frame, std::move(target));
    target = std::make_unique<OffscreenTarget>(device, size, aa);
    scene->setViewHeight(double(size.height));
  }
  swapchainStale = false;
  return true;
}

void Viewer::State::renderFrame(uint32_t image, VkCommandBuffer cmd, const Camera& cam) {
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  GLOBE_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  const uint32_t slot = uint32_t(frame % vk::kFramesInFlight);
  gpuTimer.begin(cmd, slot);

  // Scene: display-encoded colour and reversed-Z depth. The terrain's per-frame buffers are indexed by
  // frame % kFramesInFlight, the FrameRing slot whose fence begin() waited for.
  scene->prepare(cmd, cam, uint32_t(frame % vk::kFramesInFlight));
  target->begin(cmd, kSpaceColour);
  scene->record(cmd, cam, uint32_t(frame % vk::kFramesInFlight));
  target->end(cmd);  // colour is now TRANSFER_SRC_OPTIMAL
  gpuTimer.end(cmd, slot);

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
  const double step_s = options.fixedStep ? kViewerFixedStep_s : std::min(wall_s, 0.25);
  Camera cam = frameCamera(step_s, now);
  framePose = currentPose(cam);
  if (recordToggleRequested) {
    recordToggleRequested = false;
    toggleRecording(cam);
  } else if (recorder.recording()) {
    recorder.advance(step_s, framePose);
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
    if (double ms = s.gpuTimer.takeMs(uint32_t(s.frame % vk::kFramesInFlight)); ms > 0) s.gpu_ms = ms;
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
    s.stats.gpu_ms = s.gpu_ms;
    s.ring.submit(s.frame, s.swapchain.renderFinished(*image));
    if (!s.swapchain.present(*image)) s.swapchainStale = true;
    lastCamera = cam;
    s.logFrame(runStart);
    ++s.frame;
    if (s.pathEnded && !s.options.holdAtPathEnd) s.quit = true;  // the path's end is drawn
    s.takeRequestedScreenshot(cam);
  }

  return s.finishRun(lastCamera);
}

Status Viewer::State::finishRun(const Camera& lastCamera) {
  // Quitting while recording keeps the flight.
  if (recorder.recording()) stopRecording();
  GLOBE_VK_CHECK(vkDeviceWaitIdle(device.device()));
  releases.releaseAll();
  if (Status st = writeFrameTimes(); !st) return st;
  if (!options.screenshotPath.empty()) {
    if (frame == 0) return Error::inField("--screenshot", "no frame was rendered");
    return saveScreenshot(options.screenshotPath, lastCamera);
  }
  return Ok{};
}

}  // namespace globe
