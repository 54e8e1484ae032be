// globe view: the windowed viewer (GLFW + Vulkan, Dear ImGui overlay). Scriptable for tests:
// --frames, --script and --screenshot make a run deterministic and checkable under Xvfb.
#include "commands.h"
#include "engine/render/quality.h"
#include "engine/viewer/viewer.h"
#include "engine/viewer/window.h"
#include "engine/vk/device.h"
#include "options.h"
#include "planet/analysis/terrain_queries.h"
#include "planet/camera/camera.h"
#include "planet/core/atomic_file.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"
#include "planet/paths/camera_path_file.h"

#include <cstdio>
#include <filesystem>

namespace globe::cli {

namespace {

struct ViewCommandOptions {
  DeviceFlags device;
  std::string at = "20,10,2000000";
  std::string heightRef = "ground";
  std::string size = "1280x720";
  int64_t frames = 0;
  std::string script;
  std::string screenshot;
  std::string screenshotDir = ".";
  std::string screenshotFormat = "png";
  std::string planet;
  std::string mode = "terrain";
  QualityOptions quality;  // --quality, --grid, --tolerance
  BudgetOptions budget;
  std::string sun;  // --sun AZIMUTH,ELEVATION at the start; empty: the default sun
  std::string recordDir = ".";
  std::string record;
  bool noReload = false;
  bool noVsync = false;
  std::string path;  // camera path to fly, or empty for the fly camera
  bool holdAtPathEnd = false;
  std::string frameTimes;  // CSV written at exit, or empty
  std::string bookmarks;   // empty: defaultBookmarksPath()
};

// A directory option that must exist.
Status checkDirectory(const std::string& dir, const std::string& field) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return Error::inField(field, "'" + dir + "' is not a directory");
  return Ok{};
}

// Frames, script, screenshots and recording; an Error names the offending option.
Status checkViewerOptions(const ViewCommandOptions& o, ViewerOptions& viewer) {
  if (o.frames < 0) return Error::inField("--frames", "must be 0 (no limit) or more, got " + std::to_string(o.frames));
  viewer.frames = uint64_t(o.frames);
  viewer.vsync = !o.noVsync;
  if (!o.script.empty()) {
    auto script = loadInputScript(o.script, "--script");
    if (!script) return script.error();
    viewer.script = std::move(*script);
    viewer.fixedStep = true;  // scripted runs replay the same camera path at any frame rate
  }
  if (!o.screenshot.empty()) {
    if (auto s = checkWritable(o.screenshot, "--screenshot"); !s) return s;
    if (auto s = checkImageExtension(o.screenshot, "--screenshot"); !s) return s;
    viewer.screenshotPath = o.screenshot;
  }
  if (auto s = checkDirectory(o.screenshotDir, "--screenshot-dir"); !s) return s;
  viewer.screenshotDirectory = o.screenshotDir;
  viewer.screenshotExtension = "." + o.screenshotFormat;
  if (!o.path.empty()) {
    auto path = loadCameraPath(o.path);
    if (!path) return path.error();
    viewer.path = std::move(*path);
  } else if (o.holdAtPathEnd) {
    return Error::inField("--hold", "needs --path");
  }
  viewer.holdAtPathEnd = o.holdAtPathEnd;
  if (!o.frameTimes.empty()) {
    if (auto s = checkWritable(o.frameTimes, "--frame-times"); !s) return s;
    viewer.frameTimesPath = o.frameTimes;
  }
  viewer.bookmarksPath = o.bookmarks.empty() ? defaultBookmarksPath() : o.bookmarks;
  auto bookmarks = loadBookmarks(viewer.bookmarksPath);
  if (!bookmarks) return bookmarks.error();
  viewer.bookmarks = std::move(*bookmarks);
  if (auto s = checkDirectory(o.recordDir, "--record-dir"); !s) return s;
  viewer.recordDirectory = o.recordDir;
  if (!o.record.empty()) {
    if (auto s = checkWritable(o.record, "--record"); !s) return s;
    viewer.recordFile = o.record;
  }
  return Ok{};
}

// The planet (must be valid to start; later edits of the file are reloaded live, and an invalid one
// then keeps the planet on screen) and the terrain settings. Every planet error at once, like
// `globe planet check`: all but the last are printed here, the last is returned.
Status checkSceneOptions(const ViewCommandOptions& o, const GeodeticPose& pose, const std::optional<CameraPath>& path,
                         const ImageSize& size, ViewerSceneOptions& scene) {
  PlanetFileCheck planet = checkPlanetFile(o.planet);
  if (!planet.ok()) {
    const std::vector<std::string> lines = formatErrorList(planet.errors);
    for (size_t i = 0; i + 1 < lines.size(); ++i) printError(lines[i]);
    return Error{"", 0, 0, "", lines.back()};
  }
  scene.mode = o.mode == "sphere" ? ViewerMode::kSphere : ViewerMode::kTerrain;
  scene.planetPath = o.planet;
  scene.planet = std::move(planet.planet);
  scene.watch = !o.noReload;
  auto terrain = renderSettingsFromOptions(o.quality, o.budget, scene.planet, size);
  if (!terrain) return terrain.error();
  scene.terrain = *terrain;
  // The sun of `globe render` at the starting point (about 45 degrees up): the first view is lit,
  // and a viewer screenshot matches a render of the same pose.
  glm::dvec3 place = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
  std::optional<SunAngles> pathSun;
  if (path) {  // a flown path is lit like `globe bench` lights it: at its first keyframe
    const double radius_m = ElevationModel(scene.planet).radius_m();
    place = path->positionAt(path->startTime_s(), [radius_m](const glm::dvec3&) { return radius_m; });
    pathSun = path->keyframes().front().sun;
  }
  auto sun = sunFromOption(o.sun, place, pathSun);
  if (!sun) return sun.error();
  scene.sunDirection = *sun;
  return Ok{};
}

// Opens the window and the device and runs the viewer until it quits or its frames are done.
int runViewer(const ViewCommandOptions& o, const ImageSize& size, ViewerOptions viewer) {
  if (!Window::displayAvailable()) {
    printError(
        "no display: $DISPLAY is not set (globe view needs an X server; run it on a desktop or under "
        "xvfb-run, or use globe render)");
    return kExitFailure;
  }
  // The window comes first: the Device's surface must be destroyed before the window it shows.
  Window window(size.width, size.height, "globe");
  vk::DeviceOptions deviceOpts = deviceOptions(o.device);
  deviceOpts.instanceExtensions = window.requiredInstanceExtensions();
  deviceOpts.swapchain = true;
  deviceOpts.createSurface = [&window](VkInstance instance) { return window.createSurface(instance); };
  vk::Device device(deviceOpts);
  printDeviceChoice(device);

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

int runView(const ViewCommandOptions& o) {
  auto reference = parseHeightReference(o.heightRef, "--height-ref");
  if (!reference) return usageError(reference.error());
  auto pose = parsePose(o.at, "--at", *reference);
  if (!pose) return usageError(pose.error());
  auto size = parseSize(o.size, "--size");
  if (!size) return usageError(size.error());
  ViewerOptions viewer;
  viewer.pose = *pose;
  if (auto s = checkViewerOptions(o, viewer); !s) return usageError(s.error());
  if (auto s = checkSceneOptions(o, *pose, viewer.path, *size, viewer.scene); !s) return usageError(s.error());
  if (*reference == HeightReference::sphere) {
    // The viewer keeps its camera above what is drawn, like render: the same floor converts the height.
    const ElevationModel model(viewer.scene.planet);
    const glm::dvec3 down = directionFromLatLon(pose->latitude_deg, pose->longitude_deg);
    const double ground = viewer.scene.mode == ViewerMode::kSphere
                              ? model.radius_m()
                              : TerrainQueries(model).cameraFloorRadius(down, viewer.scene.terrain.ranges.maxDepth,
                                                                        viewer.scene.terrain.gridCells);
    auto above = poseAboveGround(*pose, ground, model.radius_m(), "--at");
    if (!above) return usageError(above.error());
    viewer.pose = *above;
  }
  return runViewer(o, *size, std::move(viewer));
}

}  // namespace

void addViewCommand(CLI::App& app, Runner& run) {
  auto opts = std::make_shared<ViewCommandOptions>();
  opts->planet = defaultPlanetPath();
  CLI::App* cmd = app.add_subcommand("view", "Fly around the planet in a window (needs an X display)");
  cmd->add_option("--at", opts->at,
                  "Starting camera: LAT,LON,HEIGHT[,HEADING,PITCH,ROLL] in degrees and metres above the surface "
                  "(as for render)")
      ->capture_default_str();
  addHeightReferenceOption(*cmd, opts->heightRef);
  cmd->add_option("--size", opts->size, "Window size WxH in pixels")->capture_default_str();
  cmd->add_option("--frames", opts->frames, "Quit after N frames (0: run until Esc or the window closes)")
      ->capture_default_str();
  cmd->add_option("--script", opts->script,
                  "Input script: per-frame key and mouse events (docs/viewer.md); the camera then advances "
                  "1/60 s per frame");
  cmd->add_option("--screenshot", opts->screenshot,
                  "Write the last frame (without the overlay) to FILE.png|.exr at exit");
  cmd->add_option("--screenshot-dir", opts->screenshotDir, "Directory for F12/P screenshots")->capture_default_str();
  cmd->add_option("--screenshot-format", opts->screenshotFormat,
                  "Format of F12/P screenshots: png (8-bit sRGB) or exr (half RGB + float depth Z)")
      ->check(CLI::IsMember({"png", "exr"}))
      ->capture_default_str();
  cmd->add_option("--planet", opts->planet, "Planet file (TOML); reloaded when it changes on disk")
      ->capture_default_str();
  cmd->add_flag("--no-reload", opts->noReload, "Do not watch the planet file for changes");
  cmd->add_option("--mode", opts->mode, "terrain (the planet) or sphere (its reference sphere, analytic)")
      ->check(CLI::IsMember({"terrain", "sphere"}))
      ->capture_default_str();
  addSunOption(*cmd, opts->sun);
  addQualityOptions(*cmd, opts->quality);
  addBudgetOptions(*cmd, opts->budget);
  cmd->add_option("--record-dir", opts->recordDir,
                  "Directory where R (start/stop recording) writes globe-path-YYYYmmdd-HHMMSS.path")
      ->capture_default_str();
  cmd->add_option("--record", opts->record, "Path file R writes instead (overwritten by each recording)");
  cmd->add_flag("--no-vsync", opts->noVsync, "Present without waiting for vertical blank when the surface allows");
  cmd->add_option("--path", opts->path,
                  "Fly this camera path (docs/camera-paths.md) in real time, then quit at its end");
  cmd->add_flag("--hold", opts->holdAtPathEnd, "With --path: stay open at the path's last pose");
  cmd->add_option(
      "--frame-times", opts->frameTimes,
      "Write per-frame times to FILE.csv at exit (frame, times, nodes, triangles, GPU time, camera; docs/viewer.md)");
  cmd->add_option("--bookmarks", opts->bookmarks,
                  "Bookmarks file: M saves the view there, 1-9 go back (default "
                  "$XDG_CONFIG_HOME/globe/bookmarks.txt or ~/.config/globe/bookmarks.txt)");
  addDeviceFlags(*cmd, opts->device);
  cmd->callback([opts, &run] { run = [opts] { return runView(*opts); }; });
}

}  // namespace globe::cli
