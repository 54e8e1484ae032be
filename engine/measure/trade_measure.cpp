#include "engine/measure/trade_measure.h"

#include "engine/measure/trade_images.h"
#include "engine/render/render_output.h"
#include "planet/analysis/percentile.h"

#include <algorithm>

namespace globe {

namespace {

// The knobs of one measurement and its timings, from the frames rendered.
TradeRow tradeRow(const TradeConfig& config, const TradeCamera& camera, const TerrainSettings& settings,
                  VkExtent2D size, std::vector<double> frame_ms, std::vector<double> select_ms,
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
  row.width = size.width;
  row.height = size.height;
  row.frameMedian_ms = nearestRankPercentile(frame_ms, 50);
  row.frameP95_ms = nearestRankPercentile(frame_ms, 95);
  row.select_ms = nearestRankPercentile(select_ms, 50);
  row.converged = stats.converged;
  row.triangles = stats.triangles;
  row.nodes = stats.nodes_selected;
  row.resident_mib = stats.resident_mib;
  return row;
}

// One configuration at one camera: converged, then `frames` timed frames, then the screen error.
Result<TradeRow> measureOne(TradeRig& rig, const TradeConfig& config, const TradeCamera& camera,
                            const SurfaceTruth& truth, const ImageRgba& reference) {
  TerrainSettings settings = config.settings;
  settings.style.sunDirection = defaultSunDirection(camera.camera.position_m);
  settings.viewHeight_px = double(rig.renderer.extent().height);
  // A fresh terrain per camera: resident memory and generation cost belong to this view alone.
  auto terrain = Terrain::create(rig.device, rig.model, settings);
  if (!terrain) return terrain.error();
  rig.renderer.renderFrame(**terrain, camera.camera, true);  // converge + warm-up
  std::vector<double> frame_ms, select_ms;
  FrameStats stats;
  for (uint32_t k = 0; k < rig.frames; ++k) {
    stats = rig.renderer.renderFrame(**terrain, camera.camera, true);
    frame_ms.push_back(stats.frame_ms);
    select_ms.push_back(stats.select_ms);
  }
  TradeRow row =
      tradeRow(config, camera, settings, rig.renderer.extent(), std::move(frame_ms), std::move(select_ms), stats);
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

}  // namespace

std::vector<SurfaceTruth> castTradeTruths(const ElevationModel& model, const std::vector<TradeCamera>& cameras,
                                          VkExtent2D size, uint32_t stride, const TradeProgress& progress) {
  std::vector<SurfaceTruth> truths;
  for (size_t i = 0; i < cameras.size(); ++i) {
    truths.push_back(castSurfaceTruth(model, cameras[i].camera, size.width, size.height, stride));
    if (progress) progress(double(i + 1) / double(cameras.size()));
  }
  return truths;
}

Status warmUpTrade(TradeRig& rig, const TradeConfig& config, const TradeCamera& camera) {
  TerrainSettings settings = config.settings;
  settings.viewHeight_px = double(rig.renderer.extent().height);
  auto terrain = Terrain::create(rig.device, rig.model, settings);
  if (!terrain) return terrain.error();
  rig.renderer.renderFrame(**terrain, camera.camera, false);
  rig.renderer.renderFrame(**terrain, camera.camera, false);
  return Ok{};
}

Result<std::vector<TradeRow>> measureTradeConfigs(TradeRig& rig, const std::vector<TradeConfig>& configs,
                                                  const std::vector<TradeCamera>& cameras,
                                                  const std::vector<SurfaceTruth>& truths,
                                                  const TradeProgress& progress) {
  std::vector<TradeRow> rows;
  size_t done = 0;
  for (const TradeConfig& config : configs) {
    std::vector<TradeRow> perCamera;
    for (size_t ci = 0; ci < cameras.size(); ++ci) {
      auto row = measureOne(rig, config, cameras[ci], truths[ci], rig.references[ci]);
      if (!row) return row.error();
      perCamera.push_back(std::move(*row));
      if (progress) progress(double(++done) / double(configs.size() * cameras.size()));
    }
    rows.insert(rows.end(), perCamera.begin(), perCamera.end());
    rows.push_back(aggregateTradeRows(perCamera));
  }
  return rows;
}

}  // namespace globe
