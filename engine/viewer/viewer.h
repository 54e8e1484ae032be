#pragma once
// `globe view`: the windowed frame loop. Each frame updates the planet's terrain (selection,
// streaming, generation: engine/render/terrain.h) for the fly camera, draws it into an offscreen
// target with reversed-Z depth, blits that into the swapchain image (both 8-bit UNORM in the
// display encoding of shaders/include/display_encoding.h), draws the overlay on top and presents, with two frames in
// flight. Input comes from the window and, for tests, from an input script. The planet file is watched and reloaded
// when it changes (engine/viewer/viewer_scene.h); R records the flight as a camera path.
#include "engine/viewer/bookmarks.h"
#include "engine/viewer/input_script.h"
#include "engine/viewer/viewer_scene.h"
#include "engine/vk/device.h"
#include "planet/camera/camera.h"
#include "planet/core/error.h"
#include "planet/paths/camera_path.h"

#include <memory>
#include <optional>
#include <string>

namespace globe {

class Window;

struct ViewerOptions {
  GeodeticPose pose;                         // starting camera (height above the terrain)
  ViewerSceneOptions scene;                  // planet, mode, terrain settings, sun
  uint64_t frames = 0;                       // stop after this many frames; 0 = until Esc or the window closes
  InputScript script;                        // scripted input, applied by frame number
  bool fixedStep = false;                    // advance the camera by 1/60 s per frame (deterministic runs)
  std::string screenshotPath;                // written at exit when not empty (.png or .exr)
  std::string screenshotDirectory = ".";     // where F12/P screenshots go
  std::string screenshotExtension = ".png";  // of F12/P screenshots: ".png" or ".exr" (with depth)
  std::string recordDirectory = ".";         // where R writes globe-path-YYYYmmdd-HHMMSS.path
  std::string recordFile;                    // when set, R writes this file instead (overwriting)
  bool vsync = true;                         // FIFO presentation; false prefers MAILBOX/IMMEDIATE
  // Fly this camera path instead of the fly camera: path time follows the wall clock from the first
  // frame (1/60 s per frame with fixedStep), and the viewer quits once it has drawn the path's end.
  std::optional<CameraPath> path;
  bool holdAtPathEnd = false;       // stay open at the path's last pose instead of quitting there
  std::string frameTimesPath;       // per-frame times written here at exit (CSV) when not empty
  std::string bookmarksPath;        // where M saves the view (engine/viewer/bookmarks.h)
  std::vector<Bookmark> bookmarks;  // read from it at the start
};

class Viewer {
 public:
  // Throws VulkanError on device failures; an invalid scene (terrain settings) is an Error from run().
  Viewer(Window& window, vk::Device& device, ViewerOptions options);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Runs until Esc, the window closes, the frame limit or the path's end; then writes the exit
  // screenshot and the frame times, and prints "frames N median_ms X p95_ms Y" on stdout.
  // An error is a screenshot or frame-time file that could not be written.
  Status run();

  uint64_t framesRendered() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace globe
