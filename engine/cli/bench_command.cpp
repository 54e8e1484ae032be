// globe bench: deterministic replay of a camera path, headless, with per-frame metrics, key-frame
// images and a report (docs/benchmark.md).
#include "commands.h"
#include "engine/measure/bench_flight.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/quality.h"
#include "engine/report/bench_baseline.h"
#include "engine/report/bench_frame_spool.h"
#include "engine/report/bench_metrics.h"
#include "engine/report/bench_report.h"
#include "engine/report/run_environment.h"
#include "engine/vk/device.h"
#include "globe_commit.h"
#include "options.h"
#include "planet/model/planet_file.h"
#include "planet/model/source_report.h"
#include "planet/paths/camera_path_file.h"
#include "planet/sources/source_mosaic.h"
#include "planet/surface/surface_overlay.h"
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

// The flight, with a progress bar and the terrain's warnings as they come, and when frame 0 was
// drawn (process start -> frame 0, with the warm-up).
Result<BenchFlight> flyPath(const BenchOptions& o, const BenchInputs& in, const ElevationModel& model, Terrain& terrain,
                            HeadlessRenderer& renderer, BenchFrameSpool& rows, double& firstFrame_ms) {
  ProgressBar progress("bench " + std::filesystem::path(o.path).filename().string());
  TerrainWarnings warnings;
  const BenchFlightPlan plan{&in.path, in.frames, o.rate_hz, in.keyTimes, o.mode == "converged"};
  return flyBenchPath(plan, model, terrain, renderer, rows, [&](uint64_t k) {
    if (k == 0) firstFrame_ms = millisecondsSinceProcessStart();
    printNewWarnings(warnings, terrain);
    progress.update(double(k + 1) / double(in.frames));
  });
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
void printColdStart(const BenchFlight& flight, double firstFrame_ms, const Terrain& terrain, double deviceReady_ms,
                    double pipelinesReady_ms) {
  const FrameStats& first = flight.firstFrame;
  std::printf(
      "first frame %.0f ms after process start: device %.0f ms, terrain set-up %.0f ms, frame 0 %.0f ms "
      "(of which warm-up %.0f ms in %u rounds; %u nodes drawn)\n",
      firstFrame_ms, deviceReady_ms, pipelinesReady_ms - deviceReady_ms, first.frame_ms, terrain.primeWall_ms(),
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
  double firstFrame_ms = 0.0;
  auto flight = spoolOpened ? flyPath(o, *in, model, **terrain, renderer, spool, firstFrame_ms)
                            : Result<BenchFlight>(spoolOpened.error());
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
  printColdStart(*flight, firstFrame_ms, **terrain, deviceReady_ms, pipelinesReady_ms);
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
