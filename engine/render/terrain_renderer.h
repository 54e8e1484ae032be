#pragma once
// The terrain draw (CDLOD [Strugar 2009; Frasson 2018, §3.3]): every selected node is one instance of
// ONE shared grid index buffer, its vertices pulled by the vertex shader from the node's payload slot
// (shaders/include/payload_layout.h). Two instanced draws per frame: full nodes (N x N cells) and
// partial nodes (the N/2 grid over their own payload's every other sample = their parent's LOD).
// Per-vertex morphing towards the parent's mesh from the distance to the camera, a floating origin
// (every float the GPU sees is relative to it, computed in double on the CPU first), reversed-Z with
// an infinite far plane, and flared skirts that fill sub-pixel gaps between nodes. See
// docs/rendering.md.
//
// Frames in flight: per-frame data (constants + one record per node) lives in one host-visible
// buffer per frame index, preallocated and grown only when a frame has more nodes than ever before.
// The caller must have waited for the previous use of `frameIndex` before record().
#include "engine/atmosphere/atmosphere_luts.h"
#include "engine/atmosphere/atmosphere_view.h"
#include "engine/generation/payload_pages.h"
#include "engine/render/frame_pass.h"
#include "engine/render/imagery_tiles.h"
#include "engine/render/shadow_cascades.h"
#include "engine/render/terrain_detail.h"
#include "engine/vk/frame_ring.h"
#include "engine/vk/graphics_pipeline.h"
#include "planet/camera/camera.h"
#include "planet/geometry/ellipsoid.h"
#include "planet/geometry/node_id.h"
#include "planet/lod/lod_ranges.h"
#include "planet/surface/colour_ramp.h"

#include <array>
#include <future>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace globe {

struct GridIndexRanges;       // grid_indices.h
class TerrainShadows;         // terrain_shadows.h
class AerialPerspectivePass;  // atmosphere_passes.h
class SkyPass;
struct TargetFormat;  // terrain_pipelines.h

// The surface pipelines of one colour-layer choice (surfaceShading's, terrain_pipelines.h): grids
// with back faces culled, skirt strips from both sides, the same for nodes with sea (planets with
// water only), and the grids near the camera with the land cover's splat (coverNear() only). Absent
// ones are null.
struct SurfacePipelines {
  std::unique_ptr<vk::GraphicsPipeline> solid, skirts, solidDetail, water, waterSkirts, waterDetail;
};
namespace gpu {
struct TerrainReprojectionNode;  // shaders/include/terrain_layout.h
struct TerrainFrame;
}  // namespace gpu

enum class TerrainDebugView {
  kShaded,      // lit colour ramp (normal use)
  kLodColours,  // one flat colour per drawn level
  kWireframe,   // LOD-coloured lines (falls back to kLodColours without fillModeNonSolid)
  kLandCover,   // one flat key colour per land cover class, the vertex's dominant one (shaded without land cover)
};

// Where the vertex shader takes a vertex's position from. kStored: the payload's float position
// relative to the node centre, generated once in double (the engine; the primary source's choice).
// kReprojected: the payload's height, re-projected every frame in double (face mapping, radius +
// height, minus the camera): the alternative the source rejected, only to measure it (globe trade).
enum class VertexPositions { kStored, kReprojected };

struct TerrainStyle {
  double radius_m = 6371000.0;  // planet radius (metres)
  Ellipsoid shape;              // the planet's reference surface (ElevationModel::shape); a sphere by default
  glm::dvec3 sunDirection{1.0, 0.4, 0.6};  // towards the sun, planet-fixed (normalised here)
  float ambient = 0.08f;                   // without an atmosphere: light on faces turned away from the sun, [0, 1]
  bool sky = true;                         // draw the atmosphere's sky behind the terrain (when there is one)
  // The sky the water reflects on a planet without an atmosphere (linear RGB); with one, the
  // atmosphere's own sky colours.
  glm::vec3 zenithColour{0.20f, 0.38f, 0.80f};
  glm::vec3 horizonColour{0.62f, 0.74f, 0.92f};
  // The planet's atmosphere tables (Terrain owns them; must outlive the renderer): the sky, sunlight
  // through the atmosphere and aerial perspective. nullptr: no atmosphere, black space around a
  // Lambert-lit terrain. Fixed at construction (it selects the pipelines).
  const AtmosphereLuts* atmosphere = nullptr;
  // With an atmosphere: the terrain lit by the sun and the sky through it and seen through the air
  // (terrain_atmosphere.vert). false: only the sky is the atmosphere's; the terrain is Lambert-lit,
  // as without one (AtmosphereDetail::kSky: the per-vertex light and aerial perspective cost most of
  // the atmosphere on lavapipe, docs/rendering.md "Atmosphere").
  bool aerialPerspective = true;
  // Radii (metres) of the lowest and the highest terrain: where the shadow cascades' boxes must
  // reach (ShadowView).
  glm::dvec2 terrainRadii_m{6371000.0 - 11000.0, 6371000.0 + 9000.0};
  // The same in the atmosphere's model, a sphere of radius_m under the camera (atmosphereCamera):
  // where the aerial perspective table's rays can meet the ground (AtmosphereView) and the sky's
  // lowest terrain. On a sphere the same as terrainRadii_m.
  glm::dvec2 airTerrainRadii_m{6371000.0 - 11000.0, 6371000.0 + 9000.0};
  TerrainDebugView debug = TerrainDebugView::kShaded;
  // Skirt flare, in drawn cells: outward under the neighbour and down. 0 = no skirts (cracks of a
  // fraction of a pixel may then show between nodes of different levels).
  float skirtOutward = 0.25f;
  float skirtDrop = 0.5f;
  // The planet has kept no-data holes (nodata = "hole"): fragments inside them are discarded
  // (terrain_holes.frag); off, the shader has no discard and keeps the early depth test.
  bool holes = false;
  // The planet's sea (ElevationModel::water): nodes with water are drawn with the water shader
  // (terrain_water.frag), which colours fragments below sea level per fragment.
  Water water;
  double seaLevel_m = 0.0;
  // Map cells per grid cell of the payloads' surface textures (1, 2, 4 or 8; payload_layout.h): the
  // fragment stages shade from them (PayloadPages::surfaces). 0: payloads without maps (e.g. filled
  // on the CPU), lit per vertex from the mesh's normals and albedo.
  uint32_t normalMapScale = 0;
  // Surface texture layers per slot (GpuPayloadGenerator::surfaceLayersPerSlot): 2 on a planet with an
  // overlay, whose colour layer holds the albedo per texel (payload_layout.h); 1: luma per texel,
  // chroma per vertex.
  uint32_t surfaceLayersPerSlot = 1;
  // The planet's land cover: the classes' detail textures (DetailTextureArray::descriptor(), owned
  // by the caller, alive as long as the renderer). With an image view the payloads' masks are read
  // and the fragment stages splat the textures (terrain_fragment.glsl); null: no land cover.
  VkDescriptorImageInfo detailTextures{};
  // With land cover: 0 splats the detail textures on every node; > 0 only on the nodes that may come
  // within this view depth (metres) of the camera, faded out from a third of it to it, so that the
  // nodes beyond draw without the splat's cost and look the same (DetailTextures::kNear).
  double detailRange_m = 0.0;
  // Imagery LOD (engine/render/imagery_tiles.h): the fragment stages shade from the imagery tiles'
  // maps (record() gets their binding) instead of the payloads' own (normalMapScale is then 0: the
  // mesh payloads have no maps). Stored vertex positions only.
  bool imagery = false;
  // Cast shadows of the relief (engine/render/terrain_shadows.h): the mapped fragments take the sun's
  // light through cascaded shadow maps drawn from the sun each frame (prepare()). Needs surface
  // textures (normalMapScale > 0 or imagery); ignored without.
  bool shadows = false;
  bool landCover() const { return detailTextures.imageView != VK_NULL_HANDLE; }
  // Land cover splatted on every node (the surface pipelines all have it).
  bool coverEverywhere() const { return landCover() && detailRange_m <= 0.0; }
  // Land cover splatted near the camera only (pipelines with and without it).
  bool coverNear() const { return landCover() && detailRange_m > 0.0; }
};

class TerrainRenderer {
 public:
  // The most triangles one drawn node submits: its full grid (2 per cell) and four skirt strips (2 per
  // edge cell); what a frame budget's triangle limit is counted in.
  static uint64_t maxTrianglesPerNode(uint32_t gridCells) { return 2ull * gridCells * (gridCells + 4ull); }
  // gridCells: payload grid cells per node side, a power of two in [8, 256]. initialNodes: per-frame
  // capacity allocated up front (grows when exceeded). Pipelines target OffscreenTarget's formats
  // unless `colourFormat` says otherwise (e.g. a swapchain's); `samples`: the target's samples per pixel.
  TerrainRenderer(vk::Device& device, uint32_t gridCells, const TerrainStyle& style = {},
                  VertexPositions positions = VertexPositions::kStored, uint32_t initialNodes = 1024,
                  VkFormat colourFormat = vk::kSceneColourFormat,
                  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
  ~TerrainRenderer();
  TerrainRenderer(const TerrainRenderer&) = delete;
  TerrainRenderer& operator=(const TerrainRenderer&) = delete;

  // Runs the passes' prepare() (frame_pass.h): what the frame's draws read and must be computed
  // first: with an atmosphere, the aerial perspective table for `camera` (AtmosphereView); with
  // shadows, the shadow maps of `nodes` (the casters; `groundRadius_m`: the ground's radius under the
  // camera, which the cascades are sized from). Outside the render pass, before record(); a record()
  // without it draws no shadows.
  void prepare(VkCommandBuffer cmd, const Camera& camera, const glm::dvec3& origin_m, std::span<const DrawNode> nodes,
               const PayloadPages& payloads, uint32_t frameIndex, double groundRadius_m);

  // Runs the passes' record(): the terrain, then the sky (if enabled), into the current
  // dynamic-rendering pass (viewport and scissor already set). `origin_m`: the floating origin (FloatingOrigin);
  // `payloads`: the payload pages, slot s starting at vec4 localSlot(s) * GLOBE_PAYLOAD_SLOT_VEC4(gridCells) of page
  // page(s)'s window. frameIndex < vk::kFramesInFlight.
  // `imagery`: the imagery tiles' binding when the style has imagery (else nullptr).
  DrawStats record(VkCommandBuffer cmd, const Camera& camera, const glm::dvec3& origin_m,
                   std::span<const DrawNode> nodes, const PayloadPages& payloads, uint32_t frameIndex,
                   const ImageryBinding* imagery = nullptr);

  const TerrainStyle& style() const { return style_; }
  void setStyle(const TerrainStyle& style) { style_ = style; }
  void setDebugView(TerrainDebugView view) { style_.debug = view; }
  void setPassTimestamps(PassTimestamps timestamps) { timestamps_ = timestamps; }
  bool wireframeSupported() const { return wireframe_ != nullptr; }
  // The per-frame aerial perspective tables (nullptr without an atmosphere), for tests.
  const AtmosphereView* atmosphereView() const;
  // The shadow maps (nullptr without shadows), for tests.
  const TerrainShadows* shadows() const { return shadows_.get(); }
  uint32_t gridCells() const { return cells_; }
  // Index counts of the full and the half-resolution grids, and of one skirt strip (one node edge) of each.
  uint32_t fullIndexCount() const { return count_[0]; }
  uint32_t halfIndexCount() const { return count_[1]; }
  uint32_t fullSkirtIndexCount() const { return count_[2]; }
  uint32_t halfSkirtIndexCount() const { return count_[3]; }
  // The per-frame buffer of `frameIndex`: TerrainFrame constants at offset 0, the drawn nodes'
  // TerrainInstances from instanceBytes() (then the skirt instances). Bindings of the terrain shaders (0 instances, 2
  // constants).
  const vk::Buffer& frameBuffer(uint32_t frameIndex) const { return frames_[frameIndex]; }
  VkDescriptorBufferInfo instanceDescriptor(uint32_t frameIndex) const;
  VkDescriptorBufferInfo constantsDescriptor(uint32_t frameIndex) const;
  const unsigned char* instanceBytes(uint32_t frameIndex) const;

 private:
  void ensureCapacity(uint32_t frameIndex, uint32_t nodes);
  // kReprojected: writes the camera into frame `frameIndex`'s reprojection buffer and returns its
  // per-instance array (the caller fills it in instance order).
  gpu::TerrainReprojectionNode* beginReprojection(uint32_t frameIndex, const Camera& camera);
  // record()'s steps for a non-empty node list: which edges get skirts, the frame constants (returns
  // the debug view drawn), the instances grouped by draw and written, the draws themselves.
  DrawStats recordTerrain(VkCommandBuffer cmd, const Camera& camera, const glm::dvec3& origin_m,
                          std::span<const DrawNode> nodes, const PayloadPages& payloads, uint32_t frameIndex,
                          const ImageryBinding* imagery, PassMarks& marks);
  std::array<uint32_t, 2> markSkirtedEdges(std::span<const DrawNode> nodes);
  TerrainDebugView writeFrameConstants(unsigned char* bytes, const Camera& camera, const glm::dvec3& origin_m,
                                       bool skirts) const;
  // The shadow maps' matrices and biases of the cascades prepare() drew (none: no shadows).
  void writeShadowConstants(gpu::TerrainFrame& frame) const;
  // Fills order_: the indices of `nodes` by distance from the camera, nearest first; and with
  // coverNear(), detailNode_: which nodes may come within the detail range (all in the land cover view).
  void orderNearFirst(std::span<const DrawNode> nodes, const glm::dvec3& camera_m, TerrainDebugView view);
  void groupInstances(std::span<const DrawNode> nodes, const PayloadPages& payloads, uint32_t pageCount, bool skirts);
  uint32_t writeInstances(unsigned char* bytes, const glm::dvec3& origin_m, std::span<const DrawNode> nodes,
                          const PayloadPages& payloads, uint32_t pageCount, bool skirts,
                          gpu::TerrainReprojectionNode* reprojection);
  // The images a surface draw of payload page `page` samples: the detail textures (land cover) and
  // the surface textures (the page's, or the imagery tiles').
  struct ImageSet {
    std::array<vk::ImageDescriptor, 2 + kImageryTilePages> images{};
    uint32_t count = 0;
  };
  ImageSet drawImages(const PayloadPages& payloads, uint32_t page, const ImageryBinding* imagery, bool cover) const;
  // The pipeline of draw group `group` (terrain_renderer.cpp, drawGroup) in debug view `view`.
  const vk::GraphicsPipeline& groupPipeline(uint32_t group, TerrainDebugView view) const;
  DrawStats recordDraws(VkCommandBuffer cmd, const PayloadPages& payloads, uint32_t pageCount, uint32_t frameIndex,
                        TerrainDebugView view, bool reprojected, const ImageryBinding* imagery, PassMarks& marks) const;

  vk::Device& device_;
  uint32_t cells_;
  TerrainStyle style_;
  TerrainDetailTiling detailTiling_;
  PassTimestamps timestamps_;
  const AtmosphereLuts* atmosphere_;  // the style's, for the terrain pipelines (nullptr: none)
  // The terrain's own pass: the drawn nodes' grids and skirts (recordTerrain).
  class GridsPass final : public FramePass {
   public:
    explicit GridsPass(TerrainRenderer& renderer) : renderer_(renderer) {}
    void record(VkCommandBuffer cmd, const PassFrame& frame, PassMarks& marks, DrawStats& stats) override;

   private:
    TerrainRenderer& renderer_;
  };
  std::unique_ptr<AerialPerspectivePass> aerial_;  // with atmosphere_ only
  std::unique_ptr<TerrainShadows> shadows_;        // with the style's shadows and surface textures only
  GridsPass grids_{*this};
  std::unique_ptr<SkyPass> sky_;    // with the style's atmosphere only
  std::vector<FramePass*> passes_;  // in frame order: aerial_, shadows_, grids_, sky_ (those that exist)
  // The wireframe's pipeline (null where the device draws no lines), created on a second thread while
  // the others are (pipeline creation is most of the renderer's set-up: docs/benchmark.md, "Cold start").
  static std::unique_ptr<vk::GraphicsPipeline> makeWireframe(vk::Device& device, VertexPositions positions,
                                                             TargetFormat target, bool atmosphere);
  // The index buffer's ranges uploaded to the device (first_, count_, indices_).
  void uploadIndices(const GridIndexRanges& ranges);
  std::unique_ptr<vk::GraphicsPipeline> wireframe_;
  SurfacePipelines plain_;     // without the colour layer: every node of a planet without an overlay
  SurfacePipelines coloured_;  // with an overlay: the nodes whose fragments read the colour layer
  vk::Buffer indices_;
  // Index ranges: full grid, half grid, one full skirt strip, one half skirt strip.
  std::array<uint32_t, 4> first_{};
  std::array<uint32_t, 4> count_{};
  std::array<vk::Buffer, vk::kFramesInFlight> frames_;
  std::array<uint32_t, vk::kFramesInFlight> capacity_{};
  VertexPositions positions_;
  std::array<vk::Buffer, vk::kFramesInFlight> reprojection_;  // kReprojected only
  vk::Buffer faces_;                                          // kReprojected only: the 30 faces' corners
  // Per-frame scratch for the skirt test, kept to avoid allocating every frame.
  std::vector<std::pair<uint64_t, bool>> drawn_;  // (NodeId key, partial) of every drawn node, sorted
  std::vector<uint8_t> skirtMask_;                // per drawn node: bit e = edge e has a skirt
  std::vector<double> distances_;                 // per drawn node: metres from the camera
  std::vector<uint32_t> order_;                   // drawn nodes' indices, nearest first
  std::vector<uint8_t> detailNode_;               // per drawn node: 1 = drawn with the splat (coverNear())
  // Per draw group (index range x payload page): instance count, first instance, next free one.
  std::vector<uint32_t> instancesOf_, firstInstance_, nextInstance_;
};

}  // namespace globe
