#pragma once
// The viewer's debug view for the sphere preview (F1/L): a latitude/longitude grid drawn over the
// planet, blended into the current dynamic-rendering pass without touching depth.
#include "engine/vk/graphics_pipeline.h"
#include "planet/camera/camera.h"

namespace globe {

class SphereGrid {
 public:
  explicit SphereGrid(vk::Device& device);
  // Records the grid (lines every `spacing_deg` degrees) into the current pass.
  void record(VkCommandBuffer cmd, const Camera& camera, double radius_m, double spacing_deg = 10.0) const;

 private:
  vk::GraphicsPipeline pipeline_;
};

}  // namespace globe
