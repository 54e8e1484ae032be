#pragma once
// The planet's terrain per frame: CDLOD selection (planet/), the node/payload pool and its request
// queue (planet/), GPU payload generation and the terrain draw (engine/). One object owns the
// chain camera -> selection -> requests -> generation -> payloads -> draw -> stats, so the viewer,
// the headless renderer and the benchmark run exactly the same frame.
#include "engine/generation/gpu_payload_generator.h"
#include "engine/render/antialiasing.h"
#include "engine/render/detail_texture_array.h"
#include "engine/render/imagery_tiles.h"
#include "engine/render/terrain_renderer.h"
#include "planet/analysis/frame_stats.h"
#include "planet/camera/camera.h"
#include "planet/camera/floating_origin.h"
#include "planet/lod/selection.h"
#include "planet/model/elevation_model.h"
#include "planet/streaming/payload_pool.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace globe {

// kFull: the sky, and the terrain lit through the atmosphere and seen through the air (aerial
// perspective); kSky: the atmosphere's sky and sun disc behind a Lambert-lit terrain; kOff: none, as
// for a planet without an atmosphere (black space).
enum class AtmosphereDetail { kOff, kSky, kFull };
// "off", "sky" or "full"; anything else is an Error naming `field`.
Result<AtmosphereDetail> parseAtmosphereDetail(const std::string& text, const std::string& field);
const char* atmosphereDetailName(AtmosphereDetail detail);

// On a planet with land cover, where the classes' detail textures are splatted (the _cover pipelines,
// docs/rendering.md "Land cover"): kOn on every node; kNear only on the nodes near the camera, faded
// out with distance (kGroundDetailRange_m), so the ground shows detail below ~100 m at no cost to views
// from higher up; kOff nowhere (the classes' colours per vertex).
enum class DetailTextures { kOff, kNear, kOn };
// "off", "near" or "on"; anything else is an Error naming `field`.
Result<DetailTextures> parseDetailTextures(const std::string& text, const std::string& field);
const char* detailTexturesName(DetailTextures detail);
// kNear: view depth (metres) beyond which no detail is drawn; it fades in from a third of it.
inline constexpr double kGroundDetailRange_m = 200.0;

struct TerrainSettings {
  uint32_t gridCells = 32;  // cells per node side: power of two in [8, 256]
  // Normal map cells per grid cell (1, 2, 4 or 8): each payload's normal and colour map has
  // normalMapScale * gridCells cells per side (docs/rendering.md, "Surface textures"). 0: no maps, the
  // light and colour per vertex (cheaper per fragment on lavapipe).
  uint32_t normalMapScale = 1;
  // On a planet with land cover: where the classes' detail textures are splatted per fragment (the
  // _cover pipelines); elsewhere the payloads' land cover colours (docs/rendering.md, "Land cover").
  DetailTextures detailTextures = DetailTextures::kOn;
  // Imagery LOD (engine/render/imagery_tiles.h): the normal and colour maps come from tiles of their
  // own, refined by texel magnification apart from the mesh (normalMapScale is then ignored: mesh
  // payloads carry no maps). Off: each payload's own map, at the mesh's level. Stored positions only
  // (with kReprojected, a measurement, it is off).
  bool imagery = false;
  ImagerySettings imagerySettings;
  LodRangeConfig ranges;  // view ranges, max depth, morph region
  // Height (pixels) of the image the view is drawn in: tolerance-driven ranges (ranges.tolerance_px)
  // keep the screen error within the tolerance in pixels of this height. The commands set it.
  double viewHeight_px = 720.0;
  StreamingConfig streaming;     // budgets: memory (RAM, VRAM), generation, per-frame nodes/triangles/requests
  double originThreshold_m = 0;  // floating origin re-base distance (0 = camera-relative)
  TerrainStyle style;            // shading (the planet's colour ramp); its radius is set from the planet
  // How much of the planet's [atmosphere] is drawn when it has one (its tables are computed, or read
  // from the cache, AtmosphereLuts, when the terrain is made unless kOff).
  AtmosphereDetail atmosphere = AtmosphereDetail::kFull;
  // Cast shadows of the relief from the sun (TerrainStyle::shadows; with surface textures only).
  bool shadows = false;
  GenerationPrecision generation = GenerationPrecision::kDouble;  // kFloat only to measure (globe trade)
  VertexPositions vertexPositions = VertexPositions::kStored;     // kReprojected only to measure
  uint32_t payloadSlotsPerPage = 0;  // cap on slots per payload page (0: one binding's worth; tests)
  // Warm-up before the first frame (Terrain::update's first call): generation rounds, each
  // dispatched and waited for, that make all 30 roots resident and then refine the first view,
  // so no frame shows an empty planet. Rounds, not milliseconds, so replays stay deterministic.
  // 0: start empty (tests of cold streaming).
  uint32_t primeRounds = 12;
  // The target the terrain is drawn into must be made with the same (OffscreenTarget): its samples
  // per pixel are the pipelines' (HeadlessRenderer follows the terrain's; the viewer makes its target so).
  Antialiasing antialiasing = Antialiasing::kNone;
};

// Bad settings and planets are reported as an Error naming the field.
Status validateTerrainSettings(const TerrainSettings& settings);

class Terrain {
 public:
  // `model` must outlive the terrain. Throws VulkanError / std::runtime_error on device failures;
  // settings are validated first (an Error is returned through create()).
  static Result<std::unique_ptr<Terrain>> create(vk::Device& device, const ElevationModel& model,
                                                 const TerrainSettings& settings);
  ~Terrain();

  // CPU part of frame `frame` (strictly increasing): collects finished generations, selects,
  // requests, starts new generations under the budget. The first call primes the terrain first
  // (TerrainSettings::primeRounds): it blocks until the roots and the first view's nodes are resident.
  // `completedFrame`: the newest frame whose GPU work has finished (slots only older frames used may be regenerated).
  // Returns the statistics known so far (selection and streaming); record() adds the draw's.
  const FrameStats& update(uint64_t frame, const Camera& camera, uint64_t completedFrame);
  // Records the draw of the last update(). `frameIndex`: which per-frame buffers to use (frame % 2).
  void record(VkCommandBuffer cmd, const Camera& camera, uint32_t frameIndex);
  // What record() reads and must be computed first, outside the render pass (TerrainRenderer::prepare).
  void prepare(VkCommandBuffer cmd, const Camera& camera, uint32_t frameIndex);

  // Remakes the renderer's pipelines for another anti-aliasing (the payloads stay): `globe trade`
  // times the frame with the preset's and measures depth single-sampled, at the pixel centres.
  void setAntialiasing(Antialiasing antialiasing);
  // The image height the screen-space rules (tolerance ranges, imagery) count pixels in: a resized
  // window keeps its tolerance in its own pixels. Takes effect at the next update.
  void setViewHeight(double height_px) { settings_.viewHeight_px = height_px; }

  // True when the last selection drew every node at its wanted level and nothing is queued (except
  // prefetch the full pool declined) or being generated: the view has fully converged.
  bool converged() const;
  // Blocks until every generation submitted so far has finished.
  void waitForGeneration() {
    generator_->waitIdle();
    if (imagery_) imagery_->waitIdle();
  }

  const FrameStats& stats() const { return stats_; }
  const Selection& selection() const { return selection_; }
  const PayloadPool& pool() const { return *pool_; }
  // The imagery tiles (nullptr without imagery LOD).
  const ImageryTiles* imagery() const { return imagery_.get(); }
  const ElevationModel& model() const { return model_; }
  glm::dvec3 origin() const { return origin_.origin_m(); }
  TerrainRenderer& renderer() { return *renderer_; }
  // Radius (metres from the centre) of the visible surface below a unit direction, from the CPU
  // reference: the ground, or the sea surface over lower ground (ElevationModel::visibleElevation_m).
  double groundRadius(const glm::dvec3& unitDirection) const {
    return model_.radius_m() + model_.visibleElevation_m(unitDirection);
  }
  // The radius a camera's height is measured from: the higher of the true ground and the mesh drawn
  // there at the deepest level (drawnSurfaceRadius). The drawn mesh misses the relief finer than its
  // samples and can lie metres above the true ground (7e7 m planet, depth 20); a camera placed a
  // millimetre above the true ground would then be under the mesh and see through the planet.
  double cameraGroundRadius(const glm::dvec3& unitDirection) const;
  // The payload generator (its payload buffer and slot centres), for tests and tools.
  const GpuPayloadGenerator& generator() const { return *generator_; }
  const TerrainSettings& settings() const { return settings_; }
  // Degradations so far, one line each, in the order they first happened: the frame budget made the
  // terrain coarser, the payload pool or node table was exhausted, a generation failed. The
  // commands print each once as a warning.
  std::span<const std::string> warnings() const { return warnings_; }
  // The deepest level the frame budget currently allows (the configured max depth unless limited).
  int depthCap() const { return budgeted_.depthCap(); }
  // What the LOD ranges learned from payloads so far, and setting it back (LodRanges::Observations).
  LodRanges::Observations lodObservations() const { return selector_.ranges().observations(); }
  void restoreLodObservations(const LodRanges::Observations& o) { selector_.ranges().restore(o); }
  // Generation rounds the warm-up ran (0 before the first update or with primeRounds 0).
  uint32_t primedRounds() const { return primedRounds_; }
  double primeWall_ms() const { return primeWall_ms_; }  // wall time the warm-up took
  // The atmosphere's tables, or nullptr (no atmosphere, or TerrainSettings::atmosphere off).
  const AtmosphereLuts* atmosphere() const { return atmosphere_.get(); }

 private:
  // The constructor makes the generator; create() then makes the pool from it (a bad streaming
  // budget is an Error, not an exception) and attachPool() the parts that need the pool's size.
  Terrain(vk::Device& device, const ElevationModel& model, const TerrainSettings& settings, LodSelector selector);
  void attachPool(std::unique_ptr<PayloadPool> pool);
  // One round of the chain in the pool's own frame numbering (the caller's plus the warm-up's rounds).
  void updateAt(uint64_t poolFrame, const Camera& camera, uint64_t poolCompletedFrame, bool requestAllRoots);
  void prime(uint64_t firstFrame, const Camera& camera);
  // Copies warnings not seen yet from the budget and the pool; throws when generation keeps failing.
  void gatherWarnings();
  // Appends `n`'s draw record to `out` (nothing when its payload is not resident).
  void addDrawNode(const SelectedNode& n, uint32_t imageryCell, std::vector<DrawNode>& out) const;
  // shadowNodes_ for the frame: the drawn nodes and the resident casters outside `view`.
  void gatherShadowCasters(const Camera& camera, const Frustum& view, double groundRadius_m);
  // Imagery LOD's frame after the mesh's selection (texel magnification stats into stats_), and
  // without it the texel magnification of the payloads' own maps.
  // lambda: the view's pixels per radian; groundRadius_m: the ground's radius under the camera.
  void updateImagery(uint64_t poolFrame, uint64_t poolCompletedFrame, const Camera& camera, double lambda,
                     bool requestAllRoots, double groundRadius_m);
  static bool imageryOn(const TerrainSettings& s) { return s.imagery && s.vertexPositions == VertexPositions::kStored; }
  bool imageryOn() const { return imageryOn(settings_); }
  // The mesh payloads' own surface texture scale: none when imagery tiles carry the textures.
  static uint32_t meshMapScale(const TerrainSettings& s) { return imageryOn(s) ? 0u : s.normalMapScale; }

  vk::Device& device_;
  const ElevationModel& model_;
  TerrainSettings settings_;
  LodSelector selector_;
  BudgetedSelection budgeted_;
  std::unique_ptr<GpuPayloadGenerator> generator_;
  std::unique_ptr<PayloadPool> pool_;
  std::unique_ptr<AtmosphereLuts> atmosphere_;
  std::unique_ptr<DetailTextureArray> detail_;  // the land cover's detail textures (none without)
  std::unique_ptr<ImageryTiles> imagery_;       // imagery LOD (TerrainSettings::imagery), or none
  std::optional<ImagerySelector> meshMaps_;     // without it, the payloads' maps' texel magnification
  std::unique_ptr<TerrainRenderer> renderer_;
  Selection selection_;
  std::vector<DrawNode> drawNodes_;
  // With shadows: the drawn nodes and the casters beyond the view (shadow_casters.h), what the
  // shadow maps draw, and the ground's radius under the camera they were chosen for.
  Selection casters_;
  std::vector<DrawNode> shadowNodes_;
  double shadowGroundRadius_m_ = 0.0;
  FloatingOrigin origin_;
  FrameStats stats_;
  std::vector<std::string> warnings_;
  size_t poolWarningsSeen_ = 0;
  size_t imageryWarningsSeen_ = 0;
  bool budgetWarningSeen_ = false;
  bool primed_ = false;
  uint32_t primedRounds_ = 0;  // added to the caller's frame numbers: the warm-up used pool frames too
  double primeWall_ms_ = 0;
};

}  // namespace globe
