// globe trade: measures the speed/accuracy trade of the terrain settings (docs/tradeoffs.md). Each
// configuration is rendered converged at each camera; frame time, selection time, triangles, memory
// and generation cost are recorded, and the read-back depth is compared with the exact planet
// (engine/render/frame_screen_error.h), the picture with the converged `exact` image (trade_images.h).
// Writes DIR/trade.csv, DIR/pareto.svg and DIR/pareto-image.svg, all or none.
#include "commands.h"
#include "engine/render/frame_screen_error.h"
#include "engine/render/headless_renderer.h"
#include "engine/render/quality.h"
#include "engine/render/render_output.h"
#include "engine/report/bench_metrics.h"
#include "engine/report/trade_report.h"
#include "engine/vk/device.h"
#include "options.h"
#include "planet/camera/camera_path_file.h"
#include "planet/elevation/planet_file.h"
#include "progress_bar.h"
#include "trade_images.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
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

struct TradeConfig {
  std::string name;
  TerrainSettings settings;
};

struct TradeCamera {
  std::string name;
  Camera camera;
};

std::string knobName(const TerrainSettings& s) {
  char lod[32];  // tolerance ranges ignore the multiplier: name the tolerance instead
  if (s.ranges.tolerance_px > 0)
    std::snprintf(lod, sizeof(lod), "t%gpx%s", s.ranges.tolerance_px, s.ranges.roughness ? " roughness" : "");
  else
    std::snprintf(lod, sizeof(lod), "x%g", s.ranges.distanceMultiplier);
  char text[128];
  std::snprintf(text, sizeof(text), "g%u %s d%d f%g n%u%s%s", s.gridCells, lod, s.ranges.maxDepth,
                s.ranges.morphFraction, s.normalMapScale, s.generation == GenerationPrecision::kFloat ? " float" : "",
                s.vertexPositions == VertexPositions::kReprojected ? " reprojected" : "");
  return text;
}

bool sameKnobs(const TerrainSettings& a, const TerrainSettings& b) {
  return a.gridCells == b.gridCells && a.ranges.distanceMultiplier == b.ranges.distanceMultiplier &&
         a.ranges.maxDepth == b.ranges.maxDepth && a.ranges.morphFraction == b.ranges.morphFraction &&
         a.generation == b.generation && a.vertexPositions == b.vertexPositions &&
         a.ranges.tolerance_px == b.ranges.tolerance_px && a.ranges.roughness == b.ranges.roughness &&
         a.normalMapScale == b.normalMapScale && a.detailTextures == b.detailTextures;
}

// One knob at a time around the baseline, then the presets and a few combinations.
std::vector<TradeConfig> tradeConfigs(const TerrainSettings& base, const std::string& baseName, bool quick,
                                      bool lodSweep) {
  std::vector<TradeConfig> list;
  auto add = [&](const std::string& label, TerrainSettings s) {
    for (const TradeConfig& c : list)
      if (sameKnobs(c.settings, s)) return;
    list.push_back({label.empty() ? knobName(s) : label + " (" + knobName(s) + ")", s});
  };
  add(baseName, base);
  auto vary = [&](auto set, std::initializer_list<double> values) {
    for (double v : values) {
      TerrainSettings s = base;
      set(s, v);
      add("", s);
    }
  };
  auto grid = [](TerrainSettings& s, double v) { s.gridCells = uint32_t(v); };
  auto mult = [](TerrainSettings& s, double v) {
    s.ranges.distanceMultiplier = v;
    s.ranges.tolerance_px = 0;  // a multiplier is a distance-range knob
  };
  // Tolerance-driven ranges (docs/lod.md) instead of distance ranges: the multiplier is unused.
  auto tolerance = [](TerrainSettings& s, double v) {
    s.ranges.tolerance_px = v;
    s.ranges.distanceMultiplier = 1;
  };
  // The same following the relief's roughness (docs/lod.md, "Roughness"): what the roughness buys.
  auto roughTolerance = [&](TerrainSettings& s, double v) {
    tolerance(s, v);
    s.ranges.roughness = true;
  };
  auto depth = [](TerrainSettings& s, double v) { s.ranges.maxDepth = int(v); };
  // Normal map cells per grid cell (docs/rendering.md, "Surface textures"): shading detail vs generation.
  auto normalMap = [](TerrainSettings& s, double v) { s.normalMapScale = uint32_t(v); };
  auto morph = [](TerrainSettings& s, double v) { s.ranges.morphFraction = v; };
  // Generation in float instead of double (what double buys; never a preset).
  auto precision = [](TerrainSettings& s, double v) {
    s.generation = v != 0.0 ? GenerationPrecision::kFloat : GenerationPrecision::kDouble;
  };
  // The payload's heights re-projected in double every frame instead of its stored positions.
  auto reproject = [](TerrainSettings& s, double v) {
    s.vertexPositions = v != 0.0 ? VertexPositions::kReprojected : VertexPositions::kStored;
  };
  if (lodSweep && base.gridCells >= 32) {  // around exact: sub-pixel errors, where tolerance ranges save most
    vary(mult, {0.5, 0.75, 1, 1.5, 2, 3, 4});
    vary(tolerance, {0.5, 0.75, 1, 1.5, 2, 3});
    return list;
  }
  if (lodSweep) {  // distance ranges vs tolerance-driven ranges at the baseline's grid and depth
    vary(mult, {0.25, 0.5, 0.75, 1, 1.5, 2, 4});
    vary(tolerance, {0.5, 1, 2, 3, 4, 6, 8, 16});
    vary(roughTolerance, {2, 3, 4, 6, 8, 16});
    return list;
  }
  if (quick) {  // the cheap knobs only: a minute or two on lavapipe
    vary(normalMap, {0, 1, 2, 4});
    vary(grid, {16, 32, 64});
    vary(mult, {0.5, 1, 2});
    vary(precision, {1});
    vary(reproject, {1});
    vary(tolerance, {2});
    return list;
  }
  // The presets and the knobs that do not change the triangle count much first: --configs N keeps
  // the first N.
  for (QualityPreset p : {QualityPreset::kFast, QualityPreset::kBalanced, QualityPreset::kExact})
    add(std::string(qualityPresetName(p)), terrainSettingsFor(p));
  vary(normalMap, {0, 1, 2, 4});
  vary(depth, {16, 20, 24});
  vary(morph, {0.25, 0.5});
  vary(precision, {1});
  vary(reproject, {1});
  vary(grid, {16, 32, 64, 128});
  vary(mult, {0.5, 1, 2, 4});
  for (auto [g, m] : {std::pair{16.0, 2.0}, {16.0, 4.0}, {64.0, 0.5}, {64.0, 2.0}, {128.0, 0.5}, {128.0, 1.0}}) {
    TerrainSettings s = base;
    grid(s, g);
    mult(s, m);
    add("", s);
  }
  // Finer grids with the deepest level: what ground-level cameras need for sub-pixel error.
  for (auto [g, m] : {std::pair{32.0, 1.0}, {32.0, 2.0}, {64.0, 1.0}, {64.0, 2.0}, {128.0, 1.0}}) {
    TerrainSettings s = base;
    grid(s, g);
    mult(s, m);
    depth(s, 24);
    add("", s);
  }
  // The tolerance sweep against the multiplier sweep above (docs/tradeoffs.md, "Tolerance vs distance").
  vary(tolerance, {0.5, 1, 2, 4, 8, 16});
  for (double t : {1.0, 2.0, 4.0}) {
    TerrainSettings s = base;
    grid(s, 32);
    tolerance(s, t);
    depth(s, 24);
    add("", s);
  }
  return list;
}

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  if (in >> a >> b >> c) return a + " " + b + " " + c;
  return "unknown";
}

// The checked inputs of one run: everything that can be wrong with the command line or its files.
struct TradeInputs {
  PlanetDescription planet;
  QualityPreset preset = QualityPreset::kBalanced;
  TerrainSettings baseline;  // the preset with --tolerance applied
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

// The truth does not depend on the configuration: one CPU ray cast per camera.
std::vector<SurfaceTruth> castTruths(const ElevationModel& model, const std::vector<TradeCamera>& cameras,
                                     const TradeInputs& in) {
  std::vector<SurfaceTruth> truths;
  ProgressBar progress("trade: exact surface");
  for (size_t i = 0; i < cameras.size(); ++i) {
    truths.push_back(castSurfaceTruth(model, cameras[i].camera, in.size.width, in.size.height, in.stride));
    progress.update(double(i + 1) / double(cameras.size()));
  }
  return truths;
}

// The knobs of one measurement and its timings, from the frames rendered.
TradeRow tradeRow(const TradeConfig& config, const TradeCamera& camera, const TerrainSettings& settings,
                  const TradeInputs& in, std::vector<double> frame_ms, std::vector<double> select_ms,
                  const FrameStats& stats) {
  std::sort(frame_ms.begin(), frame_ms.end());
  std::sort(select_ms.begin(), select_ms.end());
  TradeRow row;
  row.config = config.name;
  row.camera = camera.name;
  row.gridCells = settings.gridCells;
  row.distanceMultiplier = settings.ranges.distanceMultiplier;
  row.maxDepth = settings.ranges.maxDepth;
  row.morphFraction = settings.ranges.morphFraction;
  row.generation = settings.generation == GenerationPrecision::kFloat ? "float" : "double";
  row.positions = settings.vertexPositions == VertexPositions::kReprojected ? "reprojected" : "stored";
  row.lod = settings.ranges.tolerance_px <= 0 ? "distance"
            : settings.ranges.roughness       ? "tolerance-roughness"
                                              : "tolerance";
  row.tolerance_px = settings.ranges.tolerance_px;
  row.width = in.size.width;
  row.height = in.size.height;
  row.frameMedian_ms = nearestRankPercentile(frame_ms, 50);
  row.frameP95_ms = nearestRankPercentile(frame_ms, 95);
  row.select_ms = nearestRankPercentile(select_ms, 50);
  row.converged = stats.converged;
  row.triangles = stats.triangles;
  row.nodes = stats.nodes_selected;
  row.resident_mib = stats.resident_mib;
  return row;
}

// What one run renders with: the device, its renderer, the shared inputs and, per camera, the
// converged `exact` image pictures are compared with.
struct TradeRig {
  vk::Device& device;
  HeadlessRenderer& renderer;
  const ElevationModel& model;
  const TradeInputs& in;
  std::vector<ImageRgba> references;
};

// One configuration at one camera: converged, then `frames` timed frames, then the screen error.
Result<TradeRow> measure(TradeRig& rig, const TradeConfig& config, const TradeCamera& camera, const SurfaceTruth& truth,
                         const ImageRgba& reference) {
  TerrainSettings settings = config.settings;
  settings.style.sunDirection = defaultSunDirection(camera.camera.position_m);
  settings.viewHeight_px = double(rig.in.size.height);
  // A fresh terrain per camera: resident memory and generation cost belong to this view alone.
  auto terrain = Terrain::create(rig.device, rig.model, settings);
  if (!terrain) return terrain.error();
  rig.renderer.renderFrame(**terrain, camera.camera, true);  // converge + warm-up
  std::vector<double> frame_ms, select_ms;
  FrameStats stats;
  for (uint32_t k = 0; k < rig.in.frames; ++k) {
    stats = rig.renderer.renderFrame(**terrain, camera.camera, true);
    frame_ms.push_back(stats.frame_ms);
    select_ms.push_back(stats.select_ms);
  }
  TradeRow row = tradeRow(config, camera, settings, rig.in, std::move(frame_ms), std::move(select_ms), stats);
  const GpuPayloadGenerator& gen = (*terrain)->generator();
  row.genPerNode_ms = gen.nodesGenerated() ? gen.gpuTime_ms() / double(gen.nodesGenerated()) : 0.0;
  compareWithReference(row, toImage(rig.renderer.readback(), camera.camera), reference);
  // Multisampled depth is resolved from sample 0, off the pixel centre the truth is cast through:
  // the error is measured on a one-sample frame of the same nodes.
  if (settings.antialiasing == Antialiasing::kMsaa4) {
    (*terrain)->setAntialiasing(Antialiasing::kNone);
    rig.renderer.renderFrame(**terrain, camera.camera, true);
  }
  row.error = measureScreenError(truth, rig.renderer.readback(), camera.camera);
  return row;
}

// The device's first frames pay one-time costs (pipeline compilation in the driver, first
// allocations): measured first, they inflated the first configuration by 1.5-2.5x. One throwaway
// converged frame of the first configuration takes them.
Status warmUp(TradeRig& rig, const TradeConfig& config, const TradeCamera& camera) {
  TerrainSettings settings = config.settings;
  settings.viewHeight_px = double(rig.in.size.height);
  auto terrain = Terrain::create(rig.device, rig.model, settings);
  if (!terrain) return terrain.error();
  rig.renderer.renderFrame(**terrain, camera.camera, true);
  rig.renderer.renderFrame(**terrain, camera.camera, true);
  return Ok{};
}

// Every configuration at every camera; each configuration's cameras are followed by their worst.
Result<std::vector<TradeRow>> measureAll(TradeRig& rig, const std::vector<TradeConfig>& configs,
                                         const std::vector<TradeCamera>& cameras,
                                         const std::vector<SurfaceTruth>& truths) {
  std::vector<TradeRow> rows;
  ProgressBar progress("trade: configurations");
  size_t done = 0;
  for (const TradeConfig& config : configs) {
    std::vector<TradeRow> perCamera;
    for (size_t ci = 0; ci < cameras.size(); ++ci) {
      auto row = measure(rig, config, cameras[ci], truths[ci], rig.references[ci]);
      if (!row) return row.error();
      perCamera.push_back(std::move(*row));
      progress.update(double(++done) / double(configs.size() * cameras.size()));
    }
    rows.insert(rows.end(), perCamera.begin(), perCamera.end());
    rows.push_back(aggregateTradeRows(perCamera));
  }
  return rows;
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

int runTrade(const TradeOptions& o) {
  auto in = checkTradeInputs(o);
  if (!in) return usageError(in.error());
  ElevationModel model(in->planet);
  std::vector<TradeConfig> configs =
      tradeConfigs(in->baseline, std::string(qualityPresetName(in->preset)), o.quick, o.lodSweep);
  if (o.lod != "both")  // keep one LOD rule's configurations
    std::erase_if(configs,
                  [&](const TradeConfig& c) { return (c.settings.ranges.tolerance_px > 0) != (o.lod == "tolerance"); });
  if (configs.empty()) return usageError(Error::inField("--lod", "no configuration of this LOD rule to run"));
  if (o.configs) configs.resize(std::min<size_t>(configs.size(), o.configs));
  auto cameras = tradeCameras(o, *in, model);
  if (!cameras) return usageError(cameras.error());
  std::printf("globe trade: %zu configurations x %zu cameras at %ux%u, %u frames each, error every %u px; load %s\n",
              configs.size(), cameras->size(), in->size.width, in->size.height, in->frames, in->stride,
              loadAverage().c_str());
  std::fflush(stdout);
  auto start = std::chrono::steady_clock::now();
  const std::vector<SurfaceTruth> truths = castTruths(model, *cameras, *in);
  double truth_ms = 0;
  for (const SurfaceTruth& t : truths) truth_ms += t.cast_ms;

  vk::Device device(deviceOptions(o.device));
  printDeviceChoice(device);
  HeadlessRenderer renderer(device, {in->size.width, in->size.height});
  TradeRig rig{device, renderer, model, *in, {}};
  if (auto s = warmUp(rig, configs.front(), cameras->front()); !s) return usageError(s.error());
  std::vector<Camera> views;
  for (const TradeCamera& c : *cameras) views.push_back(c.camera);
  auto references = renderExactReferences(device, renderer, model, in->planet, views, double(in->size.height));
  if (!references) return usageError(references.error());
  rig.references = std::move(*references);
  auto rows = measureAll(rig, configs, *cameras, truths);
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
