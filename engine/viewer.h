#pragma once
// `globe view`: the windowed frame loop. Each frame renders the scene (for now the reference
// sphere) into an HDR offscreen target with reversed-Z depth, blits it into the swapchain image
// (the sRGB swapchain format encodes gamma), draws the overlay on top and presents, with two
// frames in flight. Input comes from the window and, for tests, from an input script.
#include "engine/device.h"
#include "engine/input_script.h"
#include "planet/camera.h"
#include "planet/error.h"

#include <memory>
#include <string>

namespace globe {

class Window;

struct ViewerOptions {
  GeodeticPose pose;                      // starting camera
  double radius_m = 6371000.0;            // reference sphere radius (metres)
  uint64_t frames = 0;                    // stop after this many frames; 0 = until Esc or the window closes
  InputScript script;                     // scripted input, applied by frame number
  bool fixedStep = false;                 // advance the camera by 1/60 s per frame (deterministic runs)
  std::string screenshotPath;             // written at exit when not empty (.png or .exr)
  std::string screenshotDirectory = ".";  // where F12/P screenshots go
  bool vsync = true;                      // FIFO presentation; false prefers MAILBOX/IMMEDIATE
};

class Viewer {
 public:
  Viewer(Window& window, vk::Device& device, ViewerOptions options);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Runs until Esc, the window closes or the frame limit; then writes the exit screenshot.
  // An error is a screenshot that could not be written.
  Status run();

  uint64_t framesRendered() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace globe
