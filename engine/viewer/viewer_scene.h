#pragma once
// What `globe view` draws: the planet's terrain (engine/render/terrain.h) or, with --mode sphere, its
// analytic reference sphere and a latitude/longitude grid. Owns the planet: the description read
// from the planet file, the ElevationModel the terrain references, and the live reload that
// rebuilds both when the file changes on disk (an invalid edit keeps the last good planet and
// reports every error). No window, swapchain or frame pacing here: the Viewer drives it.
#include "engine/render/sphere_grid.h"
#include "engine/render/sphere_preview.h"
#include "engine/render/terrain.h"
#include "engine/viewer/atmosphere_table_build.h"
#include "engine/viewer/planet_file_watcher.h"
#include "engine/vk/device.h"
#include "planet/analysis/frame_stats.h"
#include "planet/camera/camera.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_description.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace globe {

enum class ViewerMode { kTerrain, kSphere };

struct ViewerSceneOptions {
  ViewerMode mode = ViewerMode::kTerrain;
  std::string planetPath;                  // watched for changes when `watch`; empty: nothing to watch
  PlanetDescription planet;                // already read from planetPath and valid
  bool watch = true;                       // live reload
  TerrainSettings terrain;                 // grid, ranges, streaming; the radius comes from the planet
  glm::dvec3 sunDirection{1.0, 0.6, 0.4};  // towards the sun, planet-fixed (normalised)
};

// What a reload did, for the frame loop's messages.
struct ReloadOutcome {
  bool reloaded = false;        // the new planet is live
  bool unchanged = false;       // the file is valid and describes the planet already shown
  bool buildingTables = false;  // valid and new: its atmosphere tables are being built, the old planet stays
  std::vector<Error> errors;    // the file is invalid; the last good planet stays
};

class ViewerScene {
 public:
  // Bad terrain settings and device failures (VulkanError's message) are an Error; never throws.
  static Result<std::unique_ptr<ViewerScene>> create(vk::Device& device, ViewerSceneOptions options);
  ~ViewerScene();
  ViewerScene(const ViewerScene&) = delete;
  ViewerScene& operator=(const ViewerScene&) = delete;

  // Checks the planet file (at most every 250 ms) and reloads it when it changed. A planet whose
  // atmosphere tables are not cached has them built first off the frame thread
  // (AtmosphereTableBuild), the old planet drawn meanwhile; the reload itself waits for the device
  // to go idle (the old terrain's buffers may be in use by frames in flight).
  std::optional<ReloadOutcome> pollReload(PlanetFileWatcher::Clock::time_point now);

  // CPU part of viewer frame `frame`; `completedFrame` as for Terrain::update. Terrain only.
  void update(uint64_t frame, const Camera& camera, uint64_t completedFrame);
  // Records what record() reads and must be computed first, outside the render pass (Terrain::prepare).
  void prepare(VkCommandBuffer cmd, const Camera& camera, uint32_t frameIndex);
  // Records the scene into the current dynamic-rendering pass (the scene target); draw calls are
  // counted in stats().
  void record(VkCommandBuffer cmd, const Camera& camera, uint32_t frameIndex);

  // H/K turn the sun's azimuth by -/+15 degrees, U/J raise/lower it by 5 degrees, in the sky above
  // `position_m` (the camera). The sun stays where it is in the planet's frame otherwise.
  void moveSun(const glm::dvec3& position_m, double azimuth_deg, double elevation_deg);
  const glm::dvec3& sunDirection() const { return options_.sunDirection; }

  // The window's height in pixels (Terrain::setViewHeight), kept for terrains a reload builds.
  void setViewHeight(double height_px);

  // F1/L: terrain cycles shaded -> LOD colours -> wireframe; the sphere toggles its grid.
  void cycleDebugView();
  std::string debugViewName() const;

  // Ground radius below a unit direction (metres from the centre): the CPU reference height.
  double groundRadius(const glm::dvec3& unitDirection) const;
  // A camera move from `from_m` towards `to_m` that never passes through the terrain (exact surface
  // ray cast, then above the drawn mesh too; TerrainQueries::guardedMove). Sphere mode: `to_m`.
  glm::dvec3 guardedCameraMove(const glm::dvec3& from_m, const glm::dvec3& to_m, double clearance_m) const;
  // Open water below a unit direction: the planet has a sea and the ground there is below it (terrain only).
  bool seaBelow(const glm::dvec3& unitDirection) const;
  double radius_m() const { return model_->radius_m(); }
  const Ellipsoid& shape() const { return model_->shape(); }
  // The geodetic normal below a planet-fixed point (the direction from the centre on a sphere).
  glm::dvec3 normalBelow(const glm::dvec3& position_m) const {
    return shape().isSphere() ? glm::normalize(position_m) : shape().normalBelow(position_m);
  }
  const PlanetDescription& planet() const { return planet_; }
  const std::string& planetPath() const { return options_.planetPath; }
  ViewerMode mode() const { return options_.mode; }
  // True when the terrain draws everything at its wanted level and nothing is streaming (always
  // in sphere mode): a still camera then sees a final, reproducible image.
  bool converged() const { return !terrain_ || terrain_->converged(); }
  // Terrain statistics of the last update/record (zero in sphere mode, except draw calls).
  const FrameStats& stats() const { return stats_; }
  // The terrain, or null in sphere mode.
  const Terrain* terrain() const { return terrain_.get(); }

 private:
  ViewerScene(vk::Device& device, ViewerSceneOptions options);
  Status buildTerrain();
  // Makes `next` the planet on screen (a new model and terrain); back to the old one when the
  // terrain refuses it.
  ReloadOutcome switchTo(PlanetDescription next);

  vk::Device& device_;
  ViewerSceneOptions options_;
  PlanetDescription planet_;                // the last good planet
  std::unique_ptr<ElevationModel> model_;   // of planet_; the terrain references it
  std::unique_ptr<Terrain> terrain_;        // declared after model_: destroyed before it
  std::unique_ptr<SpherePreview> preview_;  // sphere mode
  std::unique_ptr<SphereGrid> grid_;
  std::optional<PlanetFileWatcher> watcher_;
  std::optional<PlanetDescription> pending_;          // valid, new, waiting for its tables
  std::unique_ptr<AtmosphereTableBuild> tableBuild_;  // pending_'s tables, being built
  TerrainDebugView debug_ = TerrainDebugView::kShaded;
  bool sphereGrid_ = false;
  FrameStats stats_;
};

}  // namespace globe
