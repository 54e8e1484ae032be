#pragma once
// FXAA [Lottes 2011, FXAA 3.11 "quality"]: a fullscreen pass that reads the finished scene colour
// and writes it again with each edge pixel blended across the edge by its estimated coverage
// (docs/rendering.md, "Anti-aliasing"). Depth is not touched.
#include "engine/vk/graphics_pipeline.h"
#include "engine/vk/vk_handles.h"

namespace globe::vk {

class FxaaPass {
 public:
  explicit FxaaPass(Device& device);

  // Records the pass into the current dynamic-rendering pass (viewport and scissor set, colour only):
  // reads `scene` (same size, SHADER_READ_ONLY_OPTIMAL layout).
  void record(VkCommandBuffer cmd, const Image& scene) const;

 private:
  UniqueSampler sampler_;
  GraphicsPipeline pipeline_;
};

}  // namespace globe::vk
