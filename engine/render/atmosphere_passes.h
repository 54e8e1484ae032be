#pragma once
// The atmosphere's two passes of the terrain's frame (frame_pass.h): the aerial perspective table the
// terrain's vertices read (prepare), and the sky behind the terrain (record). docs/rendering.md,
// "Atmosphere".
#include "engine/atmosphere/atmosphere_view.h"
#include "engine/render/frame_pass.h"
#include "engine/render/terrain_pipelines.h"
#include "engine/render/terrain_renderer.h"
#include "engine/vk/graphics_pipeline.h"

namespace globe {

class AerialPerspectivePass final : public FramePass {
 public:
  // `style`: the renderer's, read each frame (the sun, the terrain's radii); `luts` must outlive this.
  AerialPerspectivePass(vk::Device& device, const AtmosphereLuts& luts, const TerrainStyle& style)
      : style_(style), view_(device, luts) {}
  // The table of the frame's camera, then a barrier making it visible to the draws.
  void prepare(VkCommandBuffer cmd, const PassFrame& frame, PassMarks& marks) override;
  const AtmosphereView& view() const { return view_; }

 private:
  const TerrainStyle& style_;
  AtmosphereView view_;
};

class SkyPass final : public FramePass {
 public:
  // `style`: the renderer's, read each frame (the sky flag, the sun, the lowest terrain); its
  // atmosphere must be set. `grid`: the terrain's index buffer, whose full grid is the sky's screen grid.
  SkyPass(vk::Device& device, const TerrainStyle& style, TargetFormat target, uint32_t gridCells, GridRanges grid);
  // The sky goes last, behind everything: its screen grid lies at the far plane (depth 0), so the
  // depth test keeps only the pixels no terrain covered, and those are the only ones shaded.
  void record(VkCommandBuffer cmd, const PassFrame& frame, PassMarks& marks, DrawStats& stats) override;

 private:
  const TerrainStyle& style_;
  uint32_t cells_;
  GridRanges grid_;
  vk::GraphicsPipeline sky_;           // the camera inside the atmosphere
  vk::GraphicsPipeline skyFromSpace_;  // the camera outside it
};

}  // namespace globe
