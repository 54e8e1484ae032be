#include "engine/viewer/viewer_scene.h"

#include <algorithm>

#include "planet/analysis/terrain_queries.h"

#include "engine/vk/vk_check.h"
#include "planet/model/planet_file.h"

#include <cmath>

namespace globe {

Result<std::unique_ptr<ViewerScene>> ViewerScene::create(vk::Device& device, ViewerSceneOptions options) {
  if (auto s = validateTerrainSettings(options.terrain); !s) return s.error();
  try {
    std::unique_ptr<ViewerScene> scene(new ViewerScene(device, std::move(options)));
    if (scene->options_.mode == ViewerMode::kTerrain) {
      if (Status s = scene->buildTerrain(); !s) return s.error();
    } else {
      scene->preview_ = std::make_unique<SpherePreview>(device);
      scene->grid_ = std::make_unique<SphereGrid>(device);
    }
    return scene;
  } catch (const std::exception& e) {  // VulkanError and allocation: a Result never throws
    return Error::inField("", e.what());
  }
}

ViewerScene::ViewerScene(vk::Device& device, ViewerSceneOptions options)
    : device_(device),
      options_(std::move(options)),
      planet_(options_.planet),
      model_(std::make_unique<ElevationModel>(planet_)) {
  options_.sunDirection = glm::normalize(options_.sunDirection);
  if (options_.watch && !options_.planetPath.empty()) watcher_.emplace(options_.planetPath);
}

ViewerScene::~ViewerScene() {
  // The terrain's buffers may be in use by the viewer's frames in flight; a destructor cannot
  // report a failed wait, and a lost device leaves nothing to wait for.
  (void)vkDeviceWaitIdle(device_.device());
}

void ViewerScene::setViewHeight(double height_px) {
  options_.terrain.viewHeight_px = height_px;
  if (terrain_) terrain_->setViewHeight(height_px);
}

Status ViewerScene::buildTerrain() {
  TerrainSettings settings = options_.terrain;
  settings.style.sunDirection = options_.sunDirection;
  settings.style.debug = debug_;
  auto terrain = Terrain::create(device_, *model_, settings);
  if (!terrain) return terrain.error();
  terrain_ = std::move(*terrain);
  return Ok{};
}

void ViewerScene::moveSun(const glm::dvec3& position_m, double azimuth_deg, double elevation_deg) {
  SunAngles sun = sunAnglesAt(position_m, options_.sunDirection);
  sun.azimuth_deg += azimuth_deg;
  sun.elevation_deg = std::clamp(sun.elevation_deg + elevation_deg, -90.0, 90.0);
  options_.sunDirection = sunDirectionAt(position_m, sun);
  if (!terrain_) return;
  TerrainStyle style = terrain_->renderer().style();
  style.sunDirection = options_.sunDirection;
  terrain_->renderer().setStyle(style);
}

std::optional<ReloadOutcome> ViewerScene::pollReload(PlanetFileWatcher::Clock::time_point now) {
  if (watcher_ && watcher_->changed(now)) {
    PlanetFileCheck check = checkPlanetFile(watcher_->path());
    if (!check.ok()) {
      ReloadOutcome outcome;
      outcome.errors = std::move(check.errors);
      return outcome;
    }
    if (check.planet == planet_ && !pending_) {
      ReloadOutcome outcome;
      outcome.unchanged = true;  // saved without a change (or back to the planet on screen)
      return outcome;
    }
    pending_ = std::move(check.planet);  // the latest valid save wins
  }
  if (!pending_ || (tableBuild_ && !tableBuild_->done())) return std::nullopt;
  if (tableBuild_) {
    // A failed build leaves the tables to the new terrain (computed on this thread, as before);
    // validation messages count as the viewer's own.
    if (const auto& failure = tableBuild_->failure(); failure && failure->starts_with("validation: "))
      device_.validation().record(VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT, *failure);
    tableBuild_.reset();
  } else if (options_.mode == ViewerMode::kTerrain) {
    const ElevationModel next(*pending_);
    if (atmosphereTablesMissing(next, options_.terrain)) {
      tableBuild_ = std::make_unique<AtmosphereTableBuild>(device_, *next.atmosphere(), next.radius_m());
      ReloadOutcome outcome;
      outcome.buildingTables = true;
      return outcome;
    }
  }
  PlanetDescription next = std::move(*pending_);
  pending_.reset();
  if (next == planet_) {
    ReloadOutcome outcome;
    outcome.unchanged = true;
    return outcome;
  }
  return switchTo(std::move(next));
}

ReloadOutcome ViewerScene::switchTo(PlanetDescription next) {
  // A new planet: everything derived from the old one goes. The old terrain's payload buffer and
  // per-frame buffers may still be read by frames in flight, so wait for them; destroying the
  // Terrain frees its whole pool at once (no slot can outlive it), and the new Terrain generates
  // the payloads the view asks for from scratch. A reload is a rare, user-initiated event: one
  // device wait is cheaper to reason about than retiring a Terrain through the release queue.
  ReloadOutcome outcome;
  GLOBE_VK_CHECK(vkDeviceWaitIdle(device_.device()));
  terrain_.reset();
  PlanetDescription previous = std::move(planet_);
  planet_ = std::move(next);
  model_ = std::make_unique<ElevationModel>(planet_);
  if (options_.mode == ViewerMode::kTerrain) {
    if (Status s = buildTerrain(); !s) {
      // Settings the old planet accepted but the new one does not: back to the old planet.
      outcome.errors.push_back(s.error());
      planet_ = std::move(previous);
      model_ = std::make_unique<ElevationModel>(planet_);
      if (Status again = buildTerrain(); !again) throw std::runtime_error(again.error().format());
      return outcome;
    }
  }
  stats_ = FrameStats{};
  outcome.reloaded = true;
  return outcome;
}

void ViewerScene::update(uint64_t frame, const Camera& camera, uint64_t completedFrame) {
  if (terrain_) stats_ = terrain_->update(frame, camera, completedFrame);
}

void ViewerScene::prepare(VkCommandBuffer cmd, const Camera& camera, uint32_t frameIndex) {
  if (terrain_) terrain_->prepare(cmd, camera, frameIndex);
}

void ViewerScene::record(VkCommandBuffer cmd, const Camera& camera, uint32_t frameIndex) {
  if (terrain_) {
    terrain_->record(cmd, camera, frameIndex);
    stats_ = terrain_->stats();
    return;
  }
  preview_->record(cmd, camera, model_->radius_m(), options_.sunDirection);
  stats_.draw_calls = 1;
  if (sphereGrid_) {
    grid_->record(cmd, camera, model_->radius_m());
    ++stats_.draw_calls;
  }
}

void ViewerScene::cycleDebugView() {
  if (!terrain_) {
    sphereGrid_ = !sphereGrid_;
    return;
  }
  switch (debug_) {
    case TerrainDebugView::kShaded:
      debug_ = TerrainDebugView::kLodColours;
      break;
    case TerrainDebugView::kLodColours:
      debug_ = TerrainDebugView::kWireframe;
      break;
    case TerrainDebugView::kWireframe:
      debug_ = terrain_->renderer().style().landCover() ? TerrainDebugView::kLandCover : TerrainDebugView::kShaded;
      break;
    case TerrainDebugView::kLandCover:
      debug_ = TerrainDebugView::kShaded;
      break;
  }
  terrain_->renderer().setDebugView(debug_);
}

std::string ViewerScene::debugViewName() const {
  if (!terrain_) return sphereGrid_ ? "grid" : "sphere";
  switch (debug_) {
    case TerrainDebugView::kShaded:
      return "shaded";
    case TerrainDebugView::kLodColours:
      return "LOD colours";
    case TerrainDebugView::kWireframe:
      return terrain_->renderer().wireframeSupported() ? "wireframe" : "wireframe (unsupported: LOD colours)";
    case TerrainDebugView::kLandCover:
      return "land cover classes";
  }
  return "";
}

glm::dvec3 ViewerScene::guardedCameraMove(const glm::dvec3& from_m, const glm::dvec3& to_m, double clearance_m) const {
  if (!terrain_) return to_m;
  return TerrainQueries(*model_).guardedMove(from_m, to_m, clearance_m, terrain_->settings().ranges.maxDepth,
                                             terrain_->settings().gridCells);
}

double ViewerScene::groundRadius(const glm::dvec3& unitDirection) const {
  if (!terrain_) return model_->radius_m();
  // The drawn mesh can lie centimetres above the true ground: keep the camera above both.
  return terrain_->cameraGroundRadius(unitDirection);
}

bool ViewerScene::seaBelow(const glm::dvec3& unitDirection) const {
  return terrain_ && model_->drawsWater() && model_->elevation_m(unitDirection) < model_->seaLevel_m();
}

}  // namespace globe
