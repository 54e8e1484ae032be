#pragma once
// The windowed viewer's state (engine/viewer/viewer.h), shared by its frame loop (viewer.cpp) and
// what the loop reports (viewer_state.cpp: overlay, messages, screenshots, recording, frame log).
// Private to the viewer library.
#include "engine/render/offscreen_target.h"
#include "engine/render/terrain_warnings.h"
#include "engine/viewer/fly_camera.h"
#include "engine/viewer/frame_time_log.h"
#include "engine/viewer/gpu_frame_timer.h"
#include "engine/viewer/overlay.h"
#include "engine/viewer/path_recorder.h"
#include "engine/viewer/swapchain.h"
#include "engine/viewer/viewer.h"
#include "engine/viewer/viewer_bodies.h"
#include "engine/viewer/viewer_places.h"
#include "engine/viewer/window.h"
#include "engine/vk/deferred_release_queue.h"
#include "engine/vk/frame_ring.h"
#include "planet/analysis/frame_stats.h"

#include <chrono>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

namespace globe {

inline constexpr double kViewerFixedStep_s = 1.0 / 60.0;  // a scripted run's camera step

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

// Lines on stdout are how scripted runs (tests) follow the viewer: each is flushed.
void printViewerLine(const std::string& line);

using Clock = std::chrono::steady_clock;

struct Viewer::State {
  State(Window& w, vk::Device& d, ViewerOptions o);

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
  void describeCamera(OverlayView& view) const;  // from framePose
  void logFrame(Clock::time_point runStart);
  void goToAskedPlace(double aspect);
  Status writeFrameTimes() const;
  // After the last frame: the recording kept, the device idle, the frame times and the --screenshot
  // (of `lastCamera`'s view) written.
  Status finishRun(const Camera& lastCamera);
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
  std::unique_ptr<OffscreenTarget> target;  // swapchain-sized display-encoded colour + reversed-Z depth
  std::unique_ptr<ViewerScene> scene;
  std::unique_ptr<Overlay> overlay;
  FlyCamera camera;
  GpuFrameTimer gpuTimer;
  ViewerPlaces places;  // go to (G), bookmarks (M, 1-9)
  PathRecorder recorder;
  bool help = false;         // F2/I: the key help panel
  double gpu_ms = 0;         // of the last completed frame
  GeodeticPose framePose{};  // the frame's camera as a pose (height above the ground), once per frame

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

}  // namespace globe
