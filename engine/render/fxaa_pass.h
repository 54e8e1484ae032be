#pragma once
// FXAA [Lottes 2011, FXAA 3.11 "quality"]: a fullscreen pass that reads the finished scene colour
// and writes it again with each edge pixel blended across the edge by its estimated coverage
// (docs/rendering.md, "Anti-aliasing"). Depth is not touched.
//
// The scene is read from a storage buffer, not sampled: lavapipe's texel fetches cost ~5x a buffer
// load, so the pass copies the drawn image into a buffer first (one linear copy) and the shader
// reads whole texels from it.
#include "engine/vk/graphics_pipeline.h"

namespace globe {

class FxaaPass {
 public:
  FxaaPass(vk::Device& device, VkExtent2D extent);

  // Copies `scene` (vk::kSceneColourFormat, `extent`, TRANSFER_SRC_OPTIMAL) into the pass's buffer and
  // makes it visible to fragment shaders. Outside a rendering pass.
  void copy(VkCommandBuffer cmd, const vk::Image& scene) const;
  // Records the filter into the current dynamic-rendering pass (colour only, viewport set).
  void record(VkCommandBuffer cmd) const;

 private:
  VkExtent2D extent_;
  vk::Buffer pixels_;  // the scene, one packed B8G8R8A8 texel per uint, rows top down
  vk::GraphicsPipeline pipeline_;
};

}  // namespace globe
