#pragma once
// The passes of the terrain's frame, one interface (docs/architecture.md, "The frame"). Each pass may
// record work outside the frame's rendering pass that later passes read (prepare: compute, its own
// depth targets), then its draws into the rendering pass (record). TerrainRenderer runs its passes in
// order: the aerial perspective table, the shadow maps, the terrain (the sea is its shader variant),
// the sky. A new pass is a class with this interface and a place in that list; FXAA, which filters
// the finished image, is the offscreen target's (offscreen_target.h).
#include "engine/generation/payload_pages.h"
#include "planet/camera/camera.h"
#include "planet/geometry/node_id.h"
#include "planet/lod/lod_ranges.h"

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <span>

namespace globe {

struct ImageryBinding;  // imagery_tiles.h
namespace gpu {
struct TerrainFrame;  // shaders/include/terrain_layout.h
}  // namespace gpu

// The terrain's one grid index buffer (TerrainRenderer's) and its ranges: full grid, half grid, one
// full skirt strip, one half skirt strip. The passes that draw grids share it.
struct GridRanges {
  VkBuffer indices = VK_NULL_HANDLE;
  std::array<uint32_t, 4> first{}, count{};
};

// One node to draw; the caller builds these from the selection and the payload pool.
struct DrawNode {
  NodeId id;
  uint32_t slot = 0;         // payload slot holding the node's samples
  NodeMorph morph;           // metres from the camera (SelectedNode::morph)
  bool partial = false;      // drawn at half resolution (the parent's LOD) over its own quadrant
  glm::dvec3 centre_m{0.0};  // node centre the payload was generated with (PayloadJob::centre)
  bool water = false;        // the payload has sea to draw (GpuPayloadGenerator::slotHasWater)
  uint32_t imageryCell = 0;  // with imagery: the node's first cell in the frame's cell tables
  bool colourLayer = false;  // its fragments read the colour layer (GpuPayloadGenerator::slotHasColourLayer)
};

struct DrawStats {
  uint64_t triangles = 0;  // submitted, including skirts and the degenerate ones of morphed cells
  uint32_t drawCalls = 0;
  uint32_t nodes = 0;
  uint32_t partialNodes = 0;
  uint32_t skirtEdges = 0;  // node edges drawn with a skirt (those next to a level change)

  DrawStats& operator+=(const DrawStats& o) {
    triangles += o.triangles;
    drawCalls += o.drawCalls;
    nodes += o.nodes;
    partialNodes += o.partialNodes;
    skirtEdges += o.skirtEdges;
    return *this;
  }
};

// Timestamps written between the passes, at `firstQuery` + TerrainPassMark in `pool` (for the
// benchmark's GPU split; VK_NULL_HANDLE writes none): the first two by every prepare(), the other
// four by every record().
enum TerrainPassMark : uint32_t {
  kMarkShadowsBegin,
  kMarkShadowsEnd,
  kMarkGridsBegin,
  kMarkSkirtsBegin,
  kMarkSkyBegin,
  kMarkSkyEnd,
  kTerrainPassMarks
};
struct PassTimestamps {
  VkQueryPool pool = VK_NULL_HANDLE;
  uint32_t firstQuery = 0;
};

// The marks of one prepare() or record(), written in order: a pass writes its own; the ones of a pass
// that did not run are written with the next (so every frame has all of them).
class PassMarks {
 public:
  PassMarks(PassTimestamps timestamps, uint32_t first) : timestamps_(timestamps), next_(first) {}
  // Writes the marks from the next unwritten one up to and including `mark`.
  void write(VkCommandBuffer cmd, uint32_t mark);

 private:
  PassTimestamps timestamps_;
  uint32_t next_;
};

// What every pass of one frame reads.
struct PassFrame {
  const Camera& camera;
  glm::dvec3 origin_m;                      // the floating origin (FloatingOrigin): every GPU float is relative to it
  std::span<const DrawNode> nodes;          // prepare(): the shadow casters; record(): the drawn nodes
  const PayloadPages& payloads;             // slot s starts at vec4 localSlot(s) * GLOBE_PAYLOAD_SLOT_VEC4 of page(s)
  uint32_t frameIndex = 0;                  // < vk::kFramesInFlight; its last use waited for
  double groundRadius_m = 0.0;              // prepare(): the ground's radius under the camera (the cascades' size)
  const ImageryBinding* imagery = nullptr;  // record(): the imagery tiles' binding, with the style's imagery
  const gpu::TerrainFrame* constants = nullptr;  // prepare(): the camera's frame constants (no shadows yet),
                                                 // when shadows are cast; else nullptr
};

class FramePass {
 public:
  virtual ~FramePass() = default;
  // Outside any rendering pass, before record() of the same frame.
  virtual void prepare(VkCommandBuffer, const PassFrame&, PassMarks&) {}
  // Into the frame's dynamic-rendering pass (viewport and scissor set); adds what it drew to `stats`.
  virtual void record(VkCommandBuffer, const PassFrame&, PassMarks&, DrawStats&) {}
};

}  // namespace globe
