// globe view: the windowed viewer (GLFW + Vulkan, Dear ImGui overlay). Scriptable for tests:
// --frames, --script and --screenshot make a run deterministic and checkable under Xvfb.
#include "commands.h"
#include "engine/device.h"
#include "engine/viewer.h"
#include "engine/window.h"
#include "options.h"
#include "planet/atomic_file.h"
#include "planet/camera.h"

#include <cstdio>
#include <filesystem>

namespace globe::cli {

namespace {

struct ViewCommandOptions {
  DeviceFlags device;
  std::string at = "20,10,2000000";
  std::string size = "1280x720";
  int64_t frames = 0;
  std::string script;
  std::string screenshot;
  std::string screenshotDir = ".";
  bool noVsync = false;
};

int runView(const ViewCommandOptions& o) {
  auto pose = parsePose(o.at, "--at");
  if (!pose) return usageError(pose.error());
  auto size = parseSize(o.size, "--size");
  if (!size) return usageError(size.error());
  if (o.frames < 0)
    return usageError(Error{"", 0, 0, "--frames", "must be 0 (no limit) or more, got " + std::to_string(o.frames)});
  ViewerOptions viewer;
  viewer.pose = *pose;
  viewer.frames = uint64_t(o.frames);
  viewer.vsync = !o.noVsync;
  if (!o.script.empty()) {
    auto script = loadInputScript(o.script, "--script");
    if (!script) return usageError(script.error());
    viewer.script = std::move(*script);
    viewer.fixedStep = true;  // scripted runs replay the same camera path at any frame rate
  }
  if (!o.screenshot.empty()) {
    if (auto s = checkWritable(o.screenshot, "--screenshot"); !s) return usageError(s.error());
    if (auto s = checkImageExtension(o.screenshot, "--screenshot"); !s) return usageError(s.error());
    viewer.screenshotPath = o.screenshot;
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(o.screenshotDir, ec))
    return usageError(Error{"", 0, 0, "--screenshot-dir", "'" + o.screenshotDir + "' is not a directory"});
  viewer.screenshotDirectory = o.screenshotDir;

  if (!Window::displayAvailable()) {
    printError(
        "no display: $DISPLAY is not set (globe view needs an X server; run it on a desktop or under "
        "xvfb-run, or use globe render)");
    return kExitFailure;
  }
  // The window comes first: the Device's surface must be destroyed before the window it shows.
  Window window(size->width, size->height, "globe");
  vk::DeviceOptions deviceOpts = deviceOptions(o.device);
  deviceOpts.instanceExtensions = window.requiredInstanceExtensions();
  deviceOpts.swapchain = true;
  deviceOpts.createSurface = [&window](VkInstance instance) { return window.createSurface(instance); };
  vk::Device device(deviceOpts);

  Status status = Ok{};
  uint64_t frames = 0;
  {
    Viewer view(window, device, std::move(viewer));
    status = view.run();
    frames = view.framesRendered();
  }
  if (!status) {
    printError(status.error().format());
    return kExitFailure;
  }
  if (int code = validationExitCode(device); code != kExitOk) return code;
  std::printf("viewed %llu frames (%s)%s%s\n", static_cast<unsigned long long>(frames), device.name().c_str(),
              o.screenshot.empty() ? "" : ", wrote ", o.screenshot.c_str());
  return kExitOk;
}

}  // namespace

void addViewCommand(CLI::App& app, Runner& run) {
  auto opts = std::make_shared<ViewCommandOptions>();
  CLI::App* cmd = app.add_subcommand("view", "Fly around the planet in a window (needs an X display)");
  cmd->add_option("--at", opts->at,
                  "Starting camera: LAT,LON,HEIGHT[,HEADING,PITCH,ROLL] in degrees and metres above the surface "
                  "(as for render)")
      ->capture_default_str();
  cmd->add_option("--size", opts->size, "Window size WxH in pixels")->capture_default_str();
  cmd->add_option("--frames", opts->frames, "Quit after N frames (0: run until Esc or the window closes)")
      ->capture_default_str();
  cmd->add_option("--script", opts->script,
                  "Input script: per-frame key and mouse events (docs/viewer.md); the camera then advances "
                  "1/60 s per frame");
  cmd->add_option("--screenshot", opts->screenshot,
                  "Write the last frame (without the overlay) to FILE.png|.exr at exit");
  cmd->add_option("--screenshot-dir", opts->screenshotDir, "Directory for F12/P screenshots")->capture_default_str();
  cmd->add_flag("--no-vsync", opts->noVsync, "Present without waiting for vertical blank when the surface allows");
  addDeviceFlags(*cmd, opts->device);
  cmd->callback([opts, &run] { run = [opts] { return runView(*opts); }; });
}

}  // namespace globe::cli
