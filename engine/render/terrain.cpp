#include "engine/render/terrain.h"

#include "engine/render/shadow_casters.h"
#include "engine/render/terrain_shadows.h"
#include "engine/vk/vk_check.h"
#include "planet/model/relief_roughness.h"
#include "planet/sources/source_mosaic.h"
#include "planet/sources/tile_cache.h"
#include "planet/surface/surface_overlay.h"

#include "planet/geometry/triacontahedron.h"
#include "planet/lod/frustum.h"
#include "planet/streaming/payload_reference.h"
#include "shaders/include/payload_layout.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace globe {

namespace {
// Generations that fail one after the other, none succeeding, before the terrain gives up: a few
// frames' worth at the default budget (8 a frame), so a transient failure is retried.
constexpr uint32_t kGenerationFailuresBeforeGivingUp = 256;
}  // namespace

Result<AtmosphereDetail> parseAtmosphereDetail(const std::string& text, const std::string& field) {
  for (AtmosphereDetail d : {AtmosphereDetail::kOff, AtmosphereDetail::kSky, AtmosphereDetail::kFull})
    if (text == atmosphereDetailName(d)) return d;
  return Error::inField(field, "unknown atmosphere detail '" + text + "' (off, sky, full)");
}

Result<DetailTextures> parseDetailTextures(const std::string& text, const std::string& field) {
  for (DetailTextures d : {DetailTextures::kOff, DetailTextures::kNear, DetailTextures::kOn})
    if (text == detailTexturesName(d)) return d;
  return Error::inField(field, "unknown detail textures '" + text + "' (off, near, on)");
}

const char* detailTexturesName(DetailTextures detail) {
  switch (detail) {
    case DetailTextures::kOff:
      return "off";
    case DetailTextures::kNear:
      return "near";
    case DetailTextures::kOn:
      break;
  }
  return "on";
}

const char* atmosphereDetailName(AtmosphereDetail detail) {
  switch (detail) {
    case AtmosphereDetail::kOff:
      return "off";
    case AtmosphereDetail::kSky:
      return "sky";
    case AtmosphereDetail::kFull:
      break;
  }
  return "full";
}

Status validateTerrainSettings(const TerrainSettings& s) {
  if (!gpu::validGridCells(s.gridCells))
    return Error::inField("grid_cells", "must be a power of two in [8, 256], got " + std::to_string(s.gridCells));
  if (!gpu::validNormalMapScale(s.normalMapScale))
    return Error::inField("normal_map_scale", "must be 0, 1, 2, 4 or 8, got " + std::to_string(s.normalMapScale));
  if (!std::isfinite(s.originThreshold_m) || s.originThreshold_m < 0)
    return Error::inField("origin_threshold_m", "must be a finite number >= 0");
  if (!(std::isfinite(s.viewHeight_px) && s.viewHeight_px >= 1.0))
    return Error::inField("view_height_px", "must be a finite number >= 1");
  if (!(std::isfinite(s.ranges.tolerance_px) && s.ranges.tolerance_px >= 0.0))
    return Error::inField("tolerance", "must be a finite number of pixels > 0 (0: distance ranges)");
  if (auto v = validateStreamingConfig(s.streaming); !v) return v;
  return validateFrameBudget(s.streaming.budget, TerrainRenderer::maxTrianglesPerNode(s.gridCells));
}

Result<std::unique_ptr<Terrain>> Terrain::create(vk::Device& device, const ElevationModel& model,
                                                 const TerrainSettings& requested) {
  if (auto s = validateTerrainSettings(requested); !s) return s.error();
  TerrainSettings settings = requested;
  // A planet's [[imagery]] lives in the mesh payloads' surface textures (docs/imagery.md), which the
  // procedural imagery tiles would replace: its maps come from the payloads then.
  if (model.overlay() != nullptr) settings.imagery = false;
  LodConfig lod;
  lod.radius_m = model.radius_m();
  lod.flattening = model.shape().flattening();
  lod.minElevation_m = model.bounds().min_m;
  lod.maxElevation_m = model.bounds().max_m;
  lod.ranges = settings.ranges;
  // The texel rule follows the mesh payloads' own surface textures (imagery has its own selection).
  lod.ranges.texelsPerNode = settings.gridCells * meshMapScale(settings);
  auto selector = LodSelector::create(lod);
  if (!selector) return selector.error();
  if (lod.ranges.tolerance_px > 0.0 && lod.ranges.roughness)
    selector->ranges().setRoughness(reliefRoughnessMap(model, int(settings.gridCells), lod.ranges.maxDepth));
  std::unique_ptr<Terrain> terrain(new Terrain(device, model, settings, std::move(*selector)));
  if (model.landCover().class_count > 0 && settings.detailTextures != DetailTextures::kOff) {
    Result<DetailTextureSet> textures = loadDetailTextures(model.landCoverDescription(), model.seed());
    if (!textures) return textures.error();
    terrain->detail_ = std::make_unique<DetailTextureArray>(device, *textures);
  }
  // The payload buffer is bound in pages of at most maxStorageBufferRange bytes (PayloadPages), so
  // only the VRAM budget bounds the pool.
  auto pool = PayloadPool::create(settings.streaming, *terrain->generator_, model.radius_m());
  if (!pool) return pool.error();
  if (terrain->imageryOn()) {
    // Tiles may lie kImageryCellLevels below the deepest mesh nodes (the cells of their tables).
    const int maxLevel = std::min(settings.ranges.maxDepth + kImageryCellLevels, kMaxNodeLevel);
    auto imagery = ImageryTiles::create(device, model, settings.imagerySettings, settings.streaming,
                                        settings.generation, maxLevel);
    if (!imagery) return imagery.error();
    terrain->imagery_ = std::move(*imagery);
  }
  terrain->attachPool(std::move(*pool));
  if (meshMapScale(settings) == 0 && model.overlay() != nullptr && model.overlay()->hasVectors())
    terrain->warnings_.push_back(
        "the planet's vectors are drawn into the surface textures, which this preset has "
        "not: none are drawn (--normal-map-scale 1 or more, or --quality balanced)");
  return terrain;
}

Terrain::Terrain(vk::Device& device, const ElevationModel& model, const TerrainSettings& settings, LodSelector selector)
    : device_(device),
      model_(model),
      settings_(settings),
      selector_(std::move(selector)),
      budgeted_(settings.streaming.budget, TerrainRenderer::maxTrianglesPerNode(settings.gridCells),
                selector_.ranges().maxDepth()),
      origin_(settings.originThreshold_m, payloadQuantum_m(0, model.radius_m())) {
  uint32_t budget = settings.streaming.dispatchBudget;
  // Each generate() call is one batch; the pool caps jobs (not calls) in flight, so as many batches
  // as jobs can be running at once.
  uint32_t batches = settings.streaming.maxInFlight;
  generator_ =
      std::make_unique<GpuPayloadGenerator>(device, model, settings.gridCells, budget, batches, settings.generation,
                                            /*waterSurface=*/true, meshMapScale(settings));
}

void Terrain::attachPool(std::unique_ptr<PayloadPool> pool) {
  pool_ = std::move(pool);
  generator_->reserveSlots(pool_->slotCapacity(), settings_.payloadSlotsPerPage);
  TerrainStyle style = settings_.style;
  style.radius_m = model_.radius_m();
  style.shape = model_.shape();
  style.holes = model_.sources() != nullptr && model_.sources()->hasHoles();
  style.water = model_.water();
  style.seaLevel_m = model_.seaLevel_m();
  style.normalMapScale = meshMapScale(settings_);
  style.surfaceLayersPerSlot = generator_->surfaceLayersPerSlot();
  style.imagery = imagery_ != nullptr;
  if (!imagery_ && settings_.normalMapScale > 0)
    meshMaps_.emplace(ImageryConfig{}, model_.radius_m(), model_.bounds().min_m, model_.bounds().max_m, model_.shape());
  if (detail_) style.detailTextures = detail_->descriptor();
  if (settings_.detailTextures == DetailTextures::kNear) style.detailRange_m = kGroundDetailRange_m;
  if (settings_.atmosphere != AtmosphereDetail::kOff && model_.atmosphere())
    atmosphere_ = std::make_unique<AtmosphereLuts>(device_, *model_.atmosphere(), model_.radius_m());
  style.atmosphere = atmosphere_.get();
  style.aerialPerspective = settings_.atmosphere == AtmosphereDetail::kFull;
  style.shadows = settings_.shadows;
  const ElevationRange bounds = model_.bounds();
  style.terrainRadii_m = {model_.shape().polarRadius_m() + bounds.min_m, model_.radius_m() + bounds.max_m};
  style.airTerrainRadii_m = {model_.radius_m() + bounds.min_m, model_.radius_m() + bounds.max_m};
  renderer_ = std::make_unique<TerrainRenderer>(device_, settings_.gridCells, style, settings_.vertexPositions, 1024,
                                                vk::kSceneColourFormat, sampleCount(settings_.antialiasing));
  drawNodes_.reserve(4096);
}

void Terrain::setAntialiasing(Antialiasing antialiasing) {
  if (antialiasing == settings_.antialiasing) return;
  // The renderer's per-frame buffers may be in use by frames in flight.
  GLOBE_VK_CHECK(vkDeviceWaitIdle(device_.device()));
  settings_.antialiasing = antialiasing;
  renderer_ =
      std::make_unique<TerrainRenderer>(device_, settings_.gridCells, renderer_->style(), settings_.vertexPositions,
                                        1024, vk::kSceneColourFormat, sampleCount(antialiasing));
}

Terrain::~Terrain() {
  // A lost device fails the wait: its work is over then, and a destructor must not throw.
  try {
    if (generator_) generator_->waitIdle();
  } catch (const vk::VulkanError&) {
  }
}

const FrameStats& Terrain::update(uint64_t frame, const Camera& camera, uint64_t completedFrame) {
  // Source tiles are read on the source I/O thread only: a lookup here never touches the disk.
  const ScopedFrameLoopThread frameLoop;
  if (!primed_) prime(frame, camera);
  updateAt(frame + primedRounds_, camera, completedFrame + primedRounds_, false);
  return stats_;
}

void Terrain::prime(uint64_t firstFrame, const Camera& camera) {
  // Rounds of the normal chain, each waited for, so the first drawn frame already has the whole
  // planet (every root) and as much of the first view as the rounds allow. No frame is drawn in
  // between, so every earlier round counts as completed.
  primed_ = true;
  const auto start = std::chrono::steady_clock::now();
  for (uint32_t round = 0; round < settings_.primeRounds; ++round) {
    const uint64_t poolFrame = firstFrame + round;
    updateAt(poolFrame, camera, poolFrame > 0 ? poolFrame - 1 : 0, true);
    primedRounds_ = round + 1;
    if (converged()) break;
    generator_->waitIdle();
    if (imagery_) imagery_->waitIdle();
  }
  primeWall_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void Terrain::updateAt(uint64_t poolFrame, const Camera& camera, uint64_t poolCompletedFrame, bool requestAllRoots) {
  stats_ = FrameStats{};
  const double generationBefore_ms = generator_->gpuTime_ms();  // cumulative over collected batches
  pool_->beginFrame(poolFrame, camera.position_m, poolCompletedFrame);
  stats_.gpu_generation_ms = generator_->gpuTime_ms() - generationBefore_ms;

  auto start = std::chrono::steady_clock::now();
  auto frustum = Frustum::fromViewProjection(camera.projection() * camera.viewFromWorld(glm::dvec3(0.0)));
  SelectionCamera sc{camera.position_m, frustum ? &*frustum : nullptr};
  const double lambda = pixelsPerRadian(settings_.viewHeight_px, camera.verticalFov_rad);
  selector_.ranges().setPixelsPerRadian(lambda);
  Status selected = budgeted_.select(selector_, sc, *pool_, selection_);
  stats_.select_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!selected) selection_.nodes.clear();  // a non-finite camera draws nothing (the caller validated it)

  // The selection asks only for the roots in view; the warm-up makes the whole planet resident so
  // turning round never shows a hole (roots are never evicted).
  if (requestAllRoots) pool_->requestRoots(glm::length(camera.position_m));
  pool_->markUsed(selection_.nodes);
  pool_->dispatch();

  const StreamingStats& s = pool_->stats();
  stats_.nodes_selected = uint32_t(selection_.nodes.size());
  stats_.nodes_partial = selection_.stats.partial;
  stats_.gen_dispatched = s.dispatched;
  stats_.gen_in_flight = s.inFlight;
  stats_.gen_completed = s.completed;
  stats_.evicted = s.evicted;
  stats_.resident_mib = s.residentMiB;
  stats_.queue_length = s.queueLength;
  // The ground under the camera, once a frame for what sizes itself by the camera's height.
  const bool maps = imagery_ || meshMaps_;
  const double ground_m = maps || renderer_->shadows() ? groundRadius(glm::normalize(camera.position_m)) : 0.0;
  updateImagery(poolFrame, poolCompletedFrame, camera, lambda, requestAllRoots, ground_m);
  gatherWarnings();

  origin_.update(camera.position_m);

  drawNodes_.clear();
  for (size_t k = 0; k < selection_.nodes.size(); ++k)
    addDrawNode(selection_.nodes[k], uint32_t(k * kImageryCellsPerNode), drawNodes_);
  shadowNodes_.clear();
  if (renderer_->shadows() && frustum) gatherShadowCasters(camera, *frustum, ground_m);
}

void Terrain::addDrawNode(const SelectedNode& n, uint32_t imageryCell, std::vector<DrawNode>& out) const {
  auto slot = pool_->slotOf(n.id);
  if (!slot) return;  // the selection only draws resident nodes; guard anyway
  out.push_back({n.id, *slot, n.morph, n.partial, generator_->slotCentre(*slot), generator_->slotHasWater(*slot),
                 imageryCell, generator_->slotHasColourLayer(*slot)});
}

void Terrain::gatherShadowCasters(const Camera& camera, const Frustum& view, double groundRadius_m) {
  const glm::dvec3 up = glm::normalize(camera.position_m);
  const glm::dvec3 sun = glm::normalize(renderer_->style().sunDirection);
  shadowGroundRadius_m_ = groundRadius_m;
  const double reach_m = shadowReach_m(glm::length(camera.position_m) - shadowGroundRadius_m_, shadowGroundRadius_m_,
                                       sunAboveShadowLimit(up, sun));
  shadowNodes_ = drawNodes_;
  if (reach_m <= 0.0) return;
  selectShadowCasters(selector_, camera, view, sun, reach_m, budgeted_.depthCap(),
                      settings_.streaming.budget.maxDrawnNodes, *pool_, casters_);
  pool_->markUsed(casters_.nodes);  // drawn this frame: their slots are not regenerated under it
  for (const SelectedNode& n : casters_.nodes) addDrawNode(n, 0, shadowNodes_);
}

void Terrain::updateImagery(uint64_t poolFrame, uint64_t poolCompletedFrame, const Camera& camera, double lambda,
                            bool requestAllRoots, double groundRadius_m) {
  if (!imagery_ && !meshMaps_) return;  // no maps
  const double altitude_m = glm::length(camera.position_m) - groundRadius_m;
  if (!imagery_) {
    const ImageryStats s = meshMaps_->meshMapStats(camera.position_m, altitude_m, lambda, selection_.nodes,
                                                   settings_.gridCells * settings_.normalMapScale, *pool_);
    stats_.texel_magnification_px = s.maxMagnification_px;
    stats_.texel_magnification_p95_px = s.p95Magnification_px;
    return;
  }
  const double before_ms = imagery_->gpuTime_ms();
  imagery_->update(poolFrame, poolCompletedFrame, camera, altitude_m, lambda, selection_.nodes, *pool_,
                   requestAllRoots);
  stats_.gpu_generation_ms += imagery_->gpuTime_ms() - before_ms;
  const ImageryStats& s = imagery_->stats();
  stats_.texel_magnification_px = s.maxMagnification_px;
  stats_.texel_magnification_p95_px = s.p95Magnification_px;
  stats_.imagery_tiles = s.tiles;
  const StreamingStats& pool = imagery_->pool().stats();
  stats_.gen_dispatched += pool.dispatched;
  stats_.gen_in_flight += pool.inFlight;
  stats_.gen_completed += pool.completed;
  stats_.evicted += pool.evicted;
  stats_.resident_mib += pool.residentMiB;
  stats_.queue_length += pool.queueLength;
}

void Terrain::gatherWarnings() {
  if (!budgetWarningSeen_ && !budgeted_.warning().empty()) {
    budgetWarningSeen_ = true;
    warnings_.push_back(budgeted_.warning());
  }
  const std::span<const std::string> pool = pool_->warnings();
  for (; poolWarningsSeen_ < pool.size(); ++poolWarningsSeen_) warnings_.push_back(pool[poolWarningsSeen_]);
  if (imagery_) {
    const std::span<const std::string> tiles = imagery_->pool().warnings();
    for (; imageryWarningsSeen_ < tiles.size(); ++imageryWarningsSeen_)
      warnings_.push_back("imagery tiles: " + tiles[imageryWarningsSeen_]);
  }
  // A failure now and then is retried (the view draws coarser meanwhile); failing on and on is not
  // going to get better, and a frame loop waiting for convergence would never end.
  if (pool_->consecutiveFailures() >= kGenerationFailuresBeforeGivingUp)
    throw std::runtime_error("payload generation failed " + std::to_string(pool_->consecutiveFailures()) +
                             " times in a row (" + generator_->lastFailure() + "): giving up");
}

void Terrain::prepare(VkCommandBuffer cmd, const Camera& camera, uint32_t frameIndex) {
  renderer_->prepare(cmd, camera, origin_.origin_m(), shadowNodes_, generator_->pages(), frameIndex,
                     shadowGroundRadius_m_);
}

void Terrain::record(VkCommandBuffer cmd, const Camera& camera, uint32_t frameIndex) {
  ImageryBinding imagery;
  if (imagery_) imagery = imagery_->write(frameIndex);
  DrawStats d = renderer_->record(cmd, camera, origin_.origin_m(), drawNodes_, generator_->pages(), frameIndex,
                                  imagery_ ? &imagery : nullptr);
  stats_.triangles = d.triangles;
  stats_.draw_calls = d.drawCalls;
}

double Terrain::cameraGroundRadius(const glm::dvec3& unitDirection) const {
  const ScopedFrameLoopThread frameLoop;
  return std::max(groundRadius(unitDirection),
                  drawnSurfaceRadius(model_, unitDirection, settings_.ranges.maxDepth, settings_.gridCells));
}

bool Terrain::converged() const {
  const StreamingStats& s = pool_->stats();
  // Look-ahead requests that a full pool declines (it only evicts for prefetch what is farther than
  // the prefetched node) stay queued for as long as the view stays: they are not part of this view,
  // and waiting for them never ends (found by the extremes test: 2 minutes per frame at 100 000
  // rounds once 11 618 slots were resident).
  const bool onlyDeclinedPrefetch = s.dispatched == 0 && s.queueLength <= s.prefetchRequested;
  return selection_.stats.fallbacks == 0 && selection_.stats.requests == 0 && s.inFlight == 0 && !budgeted_.rising() &&
         (s.queueLength == 0 || onlyDeclinedPrefetch) && (!imagery_ || imagery_->converged());
}

}  // namespace globe
