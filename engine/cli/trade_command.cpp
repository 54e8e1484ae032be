// globe trade: measures the speed/accuracy trade of the terrain settings (docs/tradeoffs.md). Each
// configuration is rendered converged at each camera; frame time, selection time, triangles, memory
// and generation cost are recorded, and the read-back depth is compared with the exact planet
// (engine/render/frame_screen_error.h), the picture with the converged `exact` image; the sweep and the
// measurements are globe::measure's (engine/measure/trade_*.h), the options, cameras and report here.
// Writes DIR/trade.csv, DIR/pareto.svg and DIR/pareto-image.svg, all or none.
#include "commands.h"
#include "engine/measure/trade_images.h"
#include "engine/measure/trade_measure.h"
#include "engine/measure/trade_sweep.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/quality.h"
#include "engine/render/render_output.h"
#include "engine/report/bench_metrics.h"
#include "engine/report/run_environment.h"
#include "engine/report/trade_report.h"
#include "engine/vk/device.h"
#include "options.h"
#include "planet/model/planet_file.h"
#include "planet/paths/camera_path_file.h"
#include "progress_bar.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>

namespace globe::cli {

namespace {

struct TradeOptions {
  DeviceFlags device;
  std::string planet;
  std::string out = "out/trade";
  QualityOptions quality;    // baseline: --quality (empty: the planet's default_quality), --tolerance
  std::string lod = "both";  // which LOD rules to sweep: distance, tolerance or both
  std::string size;          // empty = 1280x720, --quick 320x180
  std::string path;          // path sampled for extra cameras (full sweep only)
  std::string cameras;       // comma-separated camera names to keep; empty = all
  uint32_t frames = 0;       // 0 = 11, --quick 3
  uint32_t stride = 0;       // 0 = 4
  uint32_t configs = 0;      // 0 = all
  bool quick = false;
  bool lodSweep = false;  // only distance multipliers vs tolerances around the baseline
};

// The checked inputs of one run: everything that can be wrong with the command line or its files.
struct TradeInputs {
  PlanetDescription planet;
  QualityPreset preset = QualityPreset::kBalanced;
  TerrainSettings baseline;  // the preset with --tolerance applied
  TerrainSettings exact;     // what the reference pictures are drawn with
  ImageSize size;
  uint32_t frames = 0;
  uint32_t stride = 0;  // screen error sampled every `stride` px
  std::optional<CameraPath> path;
};

// Everything is checked before DIR is touched: bad input writes nothing.
Result<TradeInputs> checkTradeInputs(const TradeOptions& o) {
  TradeInputs in;
  auto planet = loadPlanetFile(o.planet);
  if (!planet) return planet.error();
  in.planet = std::move(*planet);
  auto preset = chooseQualityPreset(o.quality.quality, in.planet);
  if (!preset) return preset.error();
  in.preset = *preset;
  auto size = parseSize(o.size.empty() ? (o.quick ? "320x180" : "1280x720") : o.size, "--size");
  if (!size) return size.error();
  in.size = *size;
  auto baseline = terrainSettingsFromOptions(o.quality, in.planet, double(in.size.height));
  if (!baseline) return baseline.error();
  in.baseline = *baseline;
  QualityOptions exactOptions;
  exactOptions.quality = "exact";
  auto exact = terrainSettingsFromOptions(exactOptions, in.planet, double(in.size.height));
  if (!exact) return exact.error();
  in.exact = *exact;
  if (o.lod != "both" && o.lod != "distance" && o.lod != "tolerance")
    return Error::inField("--lod", "must be distance, tolerance or both, got '" + o.lod + "'");
  in.frames = o.frames ? o.frames : (o.quick ? 3 : 11);
  in.stride = o.stride ? o.stride : 4;
  if (in.frames > 1000) return Error::inField("--frames", "must be within [1, 1000]");
  if (in.stride > 64) return Error::inField("--stride", "must be within [1, 64]");
  if (!o.quick && !o.path.empty()) {
    auto p = loadCameraPath(o.path);
    if (!p) return p.error();
    in.path = std::move(*p);
  }
  if (auto s = checkOutputDirectory(o.out, "--out"); !s) return s.error();
  return in;
}

// --cameras: keeps the named cameras; an unknown name is an error listing the known ones.
Status keepNamedCameras(const std::string& names, std::vector<TradeCamera>& cameras) {
  if (names.empty()) return Ok{};
  std::vector<TradeCamera> kept;
  std::string list = "," + names + ",";
  for (const TradeCamera& c : cameras)
    if (list.find("," + c.name + ",") != std::string::npos) kept.push_back(c);
  size_t count = size_t(std::count(names.begin(), names.end(), ',')) + 1;
  if (kept.size() != count) {
    std::string known;
    for (const TradeCamera& c : cameras) known += (known.empty() ? "" : ", ") + c.name;
    return Error::inField("--cameras", "unknown camera in '" + names + "' (known: " + known + ")");
  }
  cameras = std::move(kept);
  return Ok{};
}

// The standard cameras (two with --quick) and, for the full sweep, two views along the path.
Result<std::vector<TradeCamera>> tradeCameras(const TradeOptions& o, const TradeInputs& in,
                                              const ElevationModel& model) {
  const double aspect = double(in.size.width) / double(in.size.height);
  auto ground = [&](const glm::dvec3& d) { return model.radius_m() + model.visibleElevation_m(d); };
  std::vector<TradeCamera> cameras;
  for (int i : o.quick ? std::vector<int>{2, 3} : std::vector<int>{0, 1, 2, 3, 4}) {
    GeodeticPose pose = standardCameraPose(i);
    cameras.push_back(
        {standardCameraName(i), cameraFromPose(pose, ground(directionFromLatLon(pose.latitude_deg, pose.longitude_deg)),
                                               model.shape(), aspect)});
  }
  if (in.path)
    for (double t : {7.0, 12.0})
      if (t >= in.path->startTime_s() && t <= in.path->endTime_s())
        cameras.push_back(
            {"path@" + formatFixed(t, 0) + "s", in.path->cameraAt(t, model.radius_m(), aspect, ground, model.shape())});
  if (auto s = keepNamedCameras(o.cameras, cameras); !s) return s.error();
  return cameras;
}

void printWorstRows(const std::vector<TradeRow>& rows) {
  std::printf("%-34s %9s %9s %9s %9s %9s %7s %6s %5s\n", "config (worst camera)", "median_ms", "p95_ms", "err_p50",
              "err_p95", "err_max", "triMax", "ssim", "dE");
  for (const TradeRow& r : rows)
    if (r.camera == "worst")
      std::printf("%-34s %9.2f %9.2f %9.3f %9.3f %9.2f %7llu %6.3f %5.1f%s\n", r.config.c_str(), r.frameMedian_ms,
                  r.frameP95_ms, r.error.p50_px, r.error.p95_px, r.error.max_px, (unsigned long long)r.triangles,
                  r.imageSsim, r.imageColourDe,
                  r.converged ? "" : "  (not converged: the pool could not hold the view)");
}

// The sweep's configurations that --lod and --configs keep.
Result<std::vector<TradeConfig>> chosenConfigs(const TradeOptions& o, const TradeInputs& in) {
  std::vector<TradeConfig> configs =
      tradeConfigs(in.baseline, std::string(qualityPresetName(in.preset)), o.quick, o.lodSweep);
  if (o.lod != "both")  // keep one LOD rule's configurations
    std::erase_if(configs,
                  [&](const TradeConfig& c) { return (c.settings.ranges.tolerance_px > 0) != (o.lod == "tolerance"); });
  if (configs.empty()) return Error::inField("--lod", "no configuration of this LOD rule to run");
  if (o.configs) configs.resize(std::min<size_t>(configs.size(), o.configs));
  return configs;
}

int runTrade(const TradeOptions& o) {
  auto in = checkTradeInputs(o);
  if (!in) return usageError(in.error());
  ElevationModel model(in->planet);
  auto configs = chosenConfigs(o, *in);
  if (!configs) return usageError(configs.error());
  auto cameras = tradeCameras(o, *in, model);
  if (!cameras) return usageError(cameras.error());
  std::printf("globe trade: %zu configurations x %zu cameras at %ux%u, %u frames each, error every %u px; load %s\n",
              configs->size(), cameras->size(), in->size.width, in->size.height, in->frames, in->stride,
              loadAverage().c_str());
  std::fflush(stdout);
  auto start = std::chrono::steady_clock::now();
  const VkExtent2D extent{in->size.width, in->size.height};
  std::vector<SurfaceTruth> truths;
  {
    ProgressBar progress("trade: exact surface");
    truths = castTradeTruths(model, *cameras, extent, in->stride, [&](double f) { progress.update(f); });
  }
  double truth_ms = 0;
  for (const SurfaceTruth& t : truths) truth_ms += t.cast_ms;

  vk::Device device(deviceOptions(o.device));
  printDeviceChoice(device);
  HeadlessRenderer renderer(device, extent);
  TradeRig rig{device, renderer, model, in->frames, {}};
  if (auto s = warmUpTrade(rig, configs->front(), cameras->front()); !s) return usageError(s.error());
  std::vector<Camera> views;
  for (const TradeCamera& c : *cameras) views.push_back(c.camera);
  std::optional<ProgressBar> progress(std::in_place, "trade: exact images");
  const auto update = [&](double f) { progress->update(f); };
  auto references = renderExactReferences(device, renderer, model, in->exact, views, update);
  if (!references) return usageError(references.error());
  rig.references = std::move(*references);
  progress.emplace("trade: configurations");
  auto rows = measureTradeConfigs(rig, *configs, *cameras, truths, update);
  progress.reset();
  if (!rows) return usageError(rows.error());  // a configuration the terrain rejects
  double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (auto made = makeOutputDirectory(o.out, "--out"); !made) {  // checked above: an I/O failure
    printError(made.error().format());
    return kExitFailure;
  }
  std::string title = "globe trade: " + in->planet.name + ", " + std::to_string(in->size.width) + "x" +
                      std::to_string(in->size.height) + ", " + device.name() + ", load " + loadAverage();
  if (auto s = writeTradeReport(o.out, *rows, title); !s) {
    printError(s.error().format());
    return kExitFailure;
  }
  if (int code = validationExitCode(device); code != kExitOk) return code;
  printWorstRows(*rows);
  std::printf("truth ray casting %.1f s, total %.1f s; wrote %s/trade.csv, %s/pareto.svg and %s/pareto-image.svg\n",
              truth_ms * 1e-3, total_s, o.out.c_str(), o.out.c_str(), o.out.c_str());
  return kExitOk;
}

}  // namespace

void addTradeCommand(CLI::App& app, Runner& run) {
  auto opts = std::make_shared<TradeOptions>();
  opts->planet = defaultPlanetPath();
  opts->path = defaultAssetPath("paths/flyover.path");
  CLI::App* cmd = app.add_subcommand(
      "trade", "Measure the speed/accuracy trade of the terrain settings (trade.csv, pareto.svg, pareto-image.svg)");
  cmd->add_option("--planet", opts->planet, "Planet file (TOML)")->capture_default_str();
  cmd->add_option("--out", opts->out, "Output directory (trade.csv, pareto.svg, pareto-image.svg)")
      ->capture_default_str();
  cmd->add_flag("--quick", opts->quick, "Few configurations, two cameras, 320x180: about a minute");
  addQualityOptions(*cmd, opts->quality, /*withGrid=*/false);  // the baseline configuration
  cmd->add_flag("--lod-sweep", opts->lodSweep,
                "Only the LOD comparison: the baseline with distance multipliers 0.25-4 and tolerances 0.5-16 px "
                "(grid >= 32: multipliers 0.5-4, tolerances 0.5-3 px)");
  cmd->add_option("--lod", opts->lod, "LOD rules to sweep: distance, tolerance or both")->capture_default_str();
  cmd->add_option("--size", opts->size, "Image size WxH (default 1280x720, --quick 320x180)");
  cmd->add_option("--frames", opts->frames,
                  "Timed converged frames per configuration and camera (default 11, --quick 3)");
  cmd->add_option("--stride", opts->stride, "Screen error sampled every N-th pixel in x and y (default 4)")
      ->check(CLI::Range(1U, 64U));
  cmd->add_option("--cameras", opts->cameras,
                  "Only these cameras, comma-separated (orbit, 100km, 10km, 1km, 2m, path@7s, path@12s)");
  cmd->add_option("--configs", opts->configs, "Run only the first N configurations (0 = all)");
  cmd->add_option("--path", opts->path,
                  "Camera path whose t = 7 s and 12 s views join the standard cameras (full sweep)")
      ->capture_default_str();
  addDeviceFlags(*cmd, opts->device);
  cmd->callback([opts, &run] { run = [opts] { return runTrade(*opts); }; });
}

}  // namespace globe::cli
