// globe bench: deterministic replay of a camera path, headless, with per-frame metrics, key-frame
// images and a report (docs/benchmark.md).
#include "commands.h"
#include "engine/io/image_io.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/quality.h"
#include "engine/render/render_output.h"
#include "engine/report/bench_baseline.h"
#include "engine/report/bench_frame_spool.h"
#include "engine/report/bench_metrics.h"
#include "engine/report/bench_report.h"
#include "engine/report/run_environment.h"
#include "engine/vk/device.h"
#include "globe_commit.h"
#include "options.h"
#include "planet/camera/camera_orientation.h"
#include "planet/camera/camera_path_file.h"
#include "planet/elevation/planet_file.h"
#include "planet/sources/source_mosaic.h"
#include "planet/sources/source_report.h"
#include "planet/sources/surface_overlay.h"
#include "progress_bar.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

namespace globe::cli {

namespace {

// One hour of path at 60 Hz, both ends included (3600 x 60 + 1; docs/reliability.md): longer runs
// are a mistake, not a benchmark. 216 000 refused the hour the docs allow.
constexpr uint64_t kMaxBenchFrames = 216001;

struct BenchOptions {
  DeviceFlags device;
  std::string planet;
  std::string path;
  std::string out = "out/bench";
  std::string mode = "budgeted";
  std::string size = "1280x720";
  std::string keyFrames = "0,7,12,18";
  double rate_hz = 60.0;
  QualityOptions quality;  // --quality, --grid, --tolerance
  std::string baseline;    // an earlier run's output directory (its summary.json), or empty
  BudgetOptions budget;
  std::string commandLine;
  std::string sun;        // --sun AZIMUTH,ELEVATION at the path's first keyframe; empty: the default sun
  int sourceRam_MiB = 0;  // RAM budget of elevation source tiles; 0 = kDefaultSourceRamBudget
};

GenerationLatency generationLatency(const PayloadPool& pool) {
  GenerationLatency latency;
  for (uint64_t count : pool.latencyHistogram()) latency.requests += count;
  if (latency.requests == 0) return latency;
  latency.p50_frames = pool.latencyPercentile(0.50);
  latency.p95_frames = pool.latencyPercentile(0.95);
  latency.p99_frames = pool.latencyPercentile(0.99);
  return latency;
}

// Horizontal speed between two camera positions `dt_s` apart (metres per second), across the
// local vertical `up` (unit; the ellipsoid's normal below the camera).
double groundSpeed_mps(const glm::dvec3& from_m, const glm::dvec3& to_m, const glm::dvec3& up, double dt_s) {
  const glm::dvec3 step = to_m - from_m;
  return glm::length(step - glm::dot(step, up) * up) / dt_s;
}

Result<std::vector<double>> parseTimes(const std::string& text, const std::string& field) {
  std::vector<double> times;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    char* end = nullptr;
    double t = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(t) || t < 0)
      return Error::inField(field, "expected times in seconds >= 0 separated by commas, got '" + text + "'");
    times.push_back(t);
  }
  return times;
}

// Everything a run needs from the command line, checked before the output directory is touched:
// bad input writes nothing.
struct BenchInputs {
  std::optional<BenchBaseline> baseline;
  PlanetDescription planet;
  CameraPath path;
  ImageSize size;
  std::vector<double> keyTimes;
  uint64_t frames = 0;  // fixed time step in path time: frame k shows t = start + k / rate
  TerrainSettings settings;
};

Result<BenchInputs> checkBenchInputs(const BenchOptions& o) {
  std::optional<BenchBaseline> baseline;
  if (!o.baseline.empty()) {
    auto read = readBenchBaseline(o.baseline);
    if (!read) return read.error();
    baseline = std::move(*read);
  }
  auto planet = loadPlanetFile(o.planet);
  if (!planet) return planet.error();
  auto path = loadCameraPath(o.path);
  if (!path) return path.error();
  auto size = parseSize(o.size, "--size");
  if (!size) return size.error();
  auto keyTimes = parseTimes(o.keyFrames, "--keyframes");
  if (!keyTimes) return keyTimes.error();
  if (!(o.rate_hz >= 1 && o.rate_hz <= 1000)) return Error::inField("--rate", "must be within [1, 1000] Hz");
  const uint64_t frames = uint64_t(std::floor(path->duration_s() * o.rate_hz + 1e-9)) + 1;
  if (frames > kMaxBenchFrames)
    return Error::inField("--rate", fmt::format("{:g} s of path at {:g} Hz is {} frames, more than the limit of {}",
                                                path->duration_s(), o.rate_hz, frames, kMaxBenchFrames));
  auto settings = renderSettingsFromOptions(o.quality, o.budget, *planet, *size);
  if (!settings) return settings.error();
  if (auto s = checkOutputDirectory(o.out, "--out"); !s) return s.error();
  return BenchInputs{std::move(baseline), std::move(*planet), std::move(*path), *size, std::move(*keyTimes), frames,
                     std::move(*settings)};
}

// What the flight produced besides its rows (spooled to disk, so memory does not grow with the
// frame count): the key frames' PNGs (kept in memory and written with the report at the end, so an
// interrupted run never leaves new key frames beside an earlier run's csv/json/html), frame 0's
// statistics and when it was drawn (process start -> frame 0, with the warm-up).
struct BenchFlight {
  std::vector<BenchKeyFrame> keys;
  FrameStats firstFrame;
  double firstFrame_ms = 0;
};

// The key frames due at frame `k` (the frame nearest to each key time; times outside the path are
// skipped), read back and encoded.
Status keepKeyFrames(const BenchInputs& in, double rate_hz, uint64_t k, HeadlessRenderer& renderer,
                     const Camera& camera, std::vector<BenchKeyFrame>& keys) {
  for (double kt : in.keyTimes) {
    if (kt < in.path.startTime_s() || kt > in.path.endTime_s()) continue;
    if (std::llround((kt - in.path.startTime_s()) * rate_hz) != int64_t(k)) continue;
    char name[64];
    std::snprintf(name, sizeof(name), "keyframe_%05.2fs.png", kt);
    Result<std::string> png = encodePng(toImage(renderer.readback(), camera));
    if (!png) return png.error();
    keys.push_back({kt, name, std::move(*png)});
  }
  return Ok{};
}

Result<BenchFlight> flyPath(const BenchOptions& o, const BenchInputs& in, const ElevationModel& model, Terrain& terrain,
                            HeadlessRenderer& renderer, BenchFrameSpool& rows) {
  const double aspect = double(in.size.width) / double(in.size.height);
  // Heights are above the drawn mesh, like `globe render --at` and the viewer (never under it).
  GroundRadiusFn ground = [&](const glm::dvec3& d) { return terrain.cameraGroundRadius(d); };
  const bool converge = o.mode == "converged";
  BenchFlight flight;
  glm::dvec3 previousPosition_m(0.0);
  ProgressBar progress("bench " + std::filesystem::path(o.path).filename().string());
  TerrainWarnings warnings;
  for (uint64_t k = 0; k < in.frames; ++k) {
    double t = in.path.startTime_s() + double(k) / o.rate_hz;
    Camera camera = in.path.cameraAt(t, model.radius_m(), aspect, ground, model.shape());
    FrameStats stats = renderer.renderFrame(terrain, camera, converge);
    printNewWarnings(warnings, terrain);
    const glm::dvec3 below =
        model.shape().isSphere() ? glm::normalize(camera.position_m) : model.shape().normalBelow(camera.position_m);
    const double altitude = poseFromCamera(camera, ground(below), model.shape()).height_m;
    const double speed = k > 0 ? groundSpeed_mps(previousPosition_m, camera.position_m, below, 1.0 / o.rate_hz) : 0.0;
    previousPosition_m = camera.position_m;
    if (auto s = rows.append({k, t, altitude, speed, stats}); !s) return s.error();
    if (k == 0) {
      flight.firstFrame = stats;
      flight.firstFrame_ms = millisecondsSinceProcessStart();
    }
    if (auto s = keepKeyFrames(in, o.rate_hz, k, renderer, camera, flight.keys); !s) return s.error();
    progress.update(double(k + 1) / double(in.frames));
  }
  return flight;
}

BenchRunInfo runInfo(const BenchOptions& o, const vk::Device& device, const TerrainSettings& settings) {
  BenchRunInfo info{
      o.planet, o.path, o.mode, device.name(), o.size, settings.gridCells, o.commandLine, std::string(GLOBE_VERSION)};
  info.shading = std::string("aa ") + antialiasingName(settings.antialiasing) + ", normal map scale " +
                 std::to_string(settings.normalMapScale) + ", atmosphere " + atmosphereDetailName(settings.atmosphere) +
                 ", detail textures " + detailTexturesName(settings.detailTextures);
  info.driver = device.driverName() + " " + device.driverInfo();
  info.shaderCache = mesaShaderCacheState();
  info.commit = GLOBE_COMMIT;
  return info;
}

// The run in one line, last: what a person wants to know without opening the report.
void printBenchSummary(const BenchOptions& o, std::span<const BenchFrame> frames) {
  const MetricSummary frame = summarizeMetric(frames, benchMetric("frame_ms"));
  const MetricSummary gpu = summarizeMetric(frames, benchMetric("gpu_ms"));
  std::printf(
      "bench: %zu frames of %s (%s): frame median %.1f ms, p95 %.1f ms, %llu over %.1f ms; GPU median "
      "%.1f ms; report %s/report.html\n",
      frames.size(), o.path.c_str(), o.mode.c_str(), frame.median, frame.p95,
      (unsigned long long)framesOverBudget(frames), kFrameBudgetMs, gpu.median, o.out.c_str());
}

// One sun for the whole flight, placed in the sky of the path's first keyframe (--sun, else the
// path's own, else the default).
Result<glm::dvec3> flightSun(const BenchOptions& o, const BenchInputs& in, const ElevationModel& model) {
  const glm::dvec3 start = in.path.positionAt(
      in.path.startTime_s(), [&](const glm::dvec3& d) { return model.radius_m() + model.visibleElevation_m(d); });
  return sunFromOption(o.sun, start, in.path.keyframes().front().sun);
}

// The cold start, and where it went: device, terrain pipelines and buffers, warm-up, frame 0.
void printColdStart(const BenchFlight& flight, const Terrain& terrain, double deviceReady_ms,
                    double pipelinesReady_ms) {
  const FrameStats& first = flight.firstFrame;
  std::printf(
      "first frame %.0f ms after process start: device %.0f ms, terrain set-up %.0f ms, frame 0 %.0f ms "
      "(of which warm-up %.0f ms in %u rounds; %u nodes drawn)\n",
      flight.firstFrame_ms, deviceReady_ms, pipelinesReady_ms - deviceReady_ms, first.frame_ms, terrain.primeWall_ms(),
      terrain.primedRounds(), first.nodes_selected);
}

int runBench(const BenchOptions& o) {
  const std::string startedUtc = utcNowIso8601();
  const std::string loadAtStart = loadAverage();
  auto in = checkBenchInputs(o);
  if (!in) return usageError(in.error());
  ElevationModel model(in->planet);
  if (model.sources() != nullptr && o.sourceRam_MiB > 0)
    model.sources()->cache().setBudget(std::size_t(o.sourceRam_MiB) << 20);
  TerrainSettings settings = in->settings;
  auto sun = flightSun(o, *in, model);
  if (!sun) return usageError(sun.error());
  settings.style.sunDirection = *sun;
  vk::Device device(deviceOptions(o.device));
  printDeviceChoice(device);
  if (auto s = checkImageExtent(device, {in->size.width, in->size.height}, "--size"); !s) return usageError(s.error());
  const double deviceReady_ms = millisecondsSinceProcessStart();
  announceAtmosphereTables(model, settings);
  auto terrain = Terrain::create(device, model, settings);
  if (!terrain) return usageError(budgetOptionError(terrain.error()));
  if (const AtmosphereLuts* a = (*terrain)->atmosphere())
    std::printf("atmosphere tables: %s in %.0f ms\n", a->fromCache() ? "read from the cache" : "computed",
                a->build_ms());
  HeadlessRenderer renderer(device, {in->size.width, in->size.height});
  const double pipelinesReady_ms = millisecondsSinceProcessStart();
  if (auto made = makeOutputDirectory(o.out, "--out"); !made) return usageError(made.error());

  BenchFrameSpool spool;
  const Status spoolOpened = spool.open(o.out);
  auto flight =
      spoolOpened ? flyPath(o, *in, model, **terrain, renderer, spool) : Result<BenchFlight>(spoolOpened.error());
  if (!flight) {
    printError(flight.error().format());
    return kExitFailure;
  }
  auto rows = spool.rows();
  if (!rows) {
    printError(rows.error().format());
    return kExitFailure;
  }
  BenchRunInfo info = runInfo(o, device, settings);
  info.loadAverageStart = loadAtStart;
  info.loadAverageEnd = loadAverage();
  info.dateUtc = startedUtc;
  info.latency = generationLatency((*terrain)->pool());
  const BenchBaseline* baseline = in->baseline ? &*in->baseline : nullptr;
  if (auto s = writeBenchReport(o.out, info, *rows, flight->keys, baseline); !s) {
    printError(s.error().format());
    return kExitFailure;
  }
  if (int code = validationExitCode(device); code != kExitOk) return code;
  printColdStart(*flight, **terrain, deviceReady_ms, pipelinesReady_ms);
  if (const SourceMosaic* sources = model.sources())
    std::printf("%s\n", sourceStreamingSummary(*sources, (*terrain)->generator().sourceLatencies_s()).c_str());
  if (const SurfaceOverlay* overlay = model.overlay())
    std::printf("%s\n",
                imageryStreamingSummary(overlay->imagery(), (*terrain)->generator().sourceLatencies_s()).c_str());
  printBenchSummary(o, *rows);
  return kExitOk;
}

}  // namespace

void addBenchCommand(CLI::App& app, Runner& run, const std::string& commandLine) {
  auto opts = std::make_shared<BenchOptions>();
  opts->planet = defaultPlanetPath();
  opts->path = defaultAssetPath("paths/flyover.path");
  opts->commandLine = commandLine;
  CLI::App* cmd = app.add_subcommand("bench", "Replay a camera path headless and write per-frame metrics and a report");
  cmd->add_option("--planet", opts->planet, "Planet file (TOML)")->capture_default_str();
  cmd->add_option("--path", opts->path, "Camera path file (docs/camera-paths.md)")->capture_default_str();
  cmd->add_option("--out", opts->out, "Output directory (frames.csv, summary.json, timeline.svg, report.html)")
      ->capture_default_str();
  cmd->add_option("--mode", opts->mode,
                  "budgeted: normal use, generation budget per frame; converged: wait each frame until every "
                  "payload the view needs is resident (render cost alone)")
      ->check(CLI::IsMember({"budgeted", "converged"}))
      ->capture_default_str();
  cmd->add_option("--size", opts->size, "Image size WxH in pixels")->capture_default_str();
  cmd->add_option("--keyframes", opts->keyFrames, "Path times (s) whose frames are saved as PNG")
      ->capture_default_str();
  cmd->add_option("--rate", opts->rate_hz, "Frames per second of path time (fixed step)")->capture_default_str();
  addSunOption(*cmd, opts->sun);
  addQualityOptions(*cmd, opts->quality);
  addBudgetOptions(*cmd, opts->budget);
  cmd->add_option("--baseline", opts->baseline,
                  "An earlier run's output directory: its summary.json's numbers go beside this run's, with ratios");
  cmd->add_option("--source-ram-mib", opts->sourceRam_MiB,
                  "RAM budget of a planet's elevation source tiles, MiB (0: the default, 256)")
      ->check(CLI::Range(0, 65536))
      ->capture_default_str();
  addDeviceFlags(*cmd, opts->device);
  cmd->callback([opts, &run] { run = [opts] { return runBench(*opts); }; });
}

}  // namespace globe::cli
