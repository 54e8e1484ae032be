#pragma once
// Draws the planet's reference sphere analytically (ray-cast in double per pixel). Cheap and
// exact: the headless renderer's `--preview sphere` mode and the reference for camera tests.
#include "engine/vk/graphics_pipeline.h"
#include "planet/camera/camera.h"

namespace globe {

class SpherePreview {
 public:
  explicit SpherePreview(vk::Device& device);
  // Records the draw into the current dynamic-rendering pass.
  void record(VkCommandBuffer cmd, const Camera& camera, double radius_m, const glm::dvec3& sunDirection) const;

 private:
  vk::GraphicsPipeline pipeline_;
};

}  // namespace globe
