#pragma once
// The terrain's shadow maps (shadow_cascades.h): a depth image with a layer per cascade, drawn from
// the sun before the frame's pass with the frame's drawn nodes — the same meshes and morph as the
// camera's (terrain_shadow.vert), so a lit surface meets its own depth — and sampled by the
// _shadows fragment stages through a comparison sampler (2 x 2 percentage-closer filtering where
// the depth format filters linearly). Casters are the drawn nodes: relief outside the view that
// shades the view's ground casts nothing (docs/rendering.md, "Shadows").
#include "engine/render/frame_pass.h"
#include "engine/render/shadow_cascades.h"
#include "engine/render/terrain_renderer.h"
#include "engine/vk/graphics_pipeline.h"

#include <array>
#include <span>
#include <vector>

namespace globe {

// Texels per side of each cascade's map.
inline constexpr uint32_t kShadowMapResolution = 2048;

class TerrainShadows final : public FramePass {
 public:
  // `style`: the renderer's, read each frame (the sun, the terrain's radii); `grids`: the terrain's
  // index buffer (its full and half grids are drawn).
  TerrainShadows(vk::Device& device, uint32_t gridCells, const TerrainStyle& style, GridRanges grids,
                 uint32_t resolution = kShadowMapResolution);
  ~TerrainShadows() override;
  TerrainShadows(const TerrainShadows&) = delete;
  TerrainShadows& operator=(const TerrainShadows&) = delete;

  // Fits the cascades to the camera and the ground under it and records every cascade's depth pass
  // of the frame's casters (none: no cascades), between the shadow marks; afterwards the maps are
  // ready for the fragment stages. The frame's constants (the morph and the floating origin) are
  // copied per cascade with the cascade's matrix.
  void prepare(VkCommandBuffer cmd, const PassFrame& frame, PassMarks& marks) override;
  // The cascades of the frame prepare() drew the maps for, until endFrame() (the frame is drawn).
  const ShadowCascades& cascades() const { return cascades_; }
  void endFrame() { cascades_ = {}; }

  // The maps for GLOBE_TERRAIN_SHADOW_BINDING.
  vk::ImageDescriptor sampled() const;
  uint32_t resolution() const { return resolution_; }
  // Nodes drawn into each cascade by the last record() (tests).
  const std::array<uint32_t, kShadowCascades>& casters() const { return casters_; }

 private:
  // Groups the nodes each cascade's box may hold by (cascade, full or half grid, page) and writes their
  // instances after the cascades' frame constants in frameIndex's buffer.
  void writeInstances(const ShadowCascades& cascades, const gpu::TerrainFrame& frame, std::span<const DrawNode> nodes,
                      const glm::dvec3& origin_m, const glm::dvec3& camera_m, const PayloadPages& payloads,
                      uint32_t frameIndex);
  void ensureCapacity(uint32_t frameIndex, size_t instances);
  // The depth passes of cascades_ (frame.constants set).
  void record(VkCommandBuffer cmd, const PassFrame& frame);
  void recordCascade(VkCommandBuffer cmd, uint32_t cascade, const PayloadPages& payloads, uint32_t frameIndex) const;

  vk::Device& device_;
  uint32_t cells_;
  const TerrainStyle& style_;
  GridRanges grids_;
  ShadowCascades cascades_;
  uint32_t resolution_;
  vk::UniqueMemory memory_;
  vk::UniqueImage image_;
  vk::UniqueImageView arrayView_;
  std::array<vk::UniqueImageView, kShadowCascades> layerViews_;
  vk::UniqueSampler sampler_;
  vk::GraphicsPipeline pipeline_;
  std::array<vk::Buffer, vk::kFramesInFlight> frames_;
  std::array<size_t, vk::kFramesInFlight> capacity_{};
  uint32_t pageCount_ = 1;
  // Per group (cascade x grid x page): instance count and first instance.
  std::vector<uint32_t> instancesOf_, firstInstance_;
  std::vector<std::pair<uint32_t, uint32_t>> members_;  // (group, node index), sorted by group
  std::vector<gpu::TerrainInstance> nodeInstances_;     // per node drawn into any cascade: its record
  std::array<uint32_t, kShadowCascades> casters_{};
};

}  // namespace globe
