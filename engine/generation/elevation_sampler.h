#pragma once
// Evaluates the elevation function on the GPU, in double, at many directions at once. Used to
// test the shader against the CPU reference and to measure samples per second; terrain payloads
// use the same include (shaders/include/elevation.glsl) from their own kernel. The parameters are
// bound as a uniform buffer (binding 0), the directions and heights as storage buffers.
#include "engine/vk/compute_pipeline.h"
#include "planet/elevation/elevation.h"

#include <glm/vec3.hpp>
#include <vector>

namespace globe {

class ElevationSampler {
 public:
  ElevationSampler(vk::Device& device, const gpu::ElevationParams& params, uint32_t capacity);

  // Elevation (metres above radius) at each unit direction; at most capacity() per call.
  std::vector<double> sample(const std::vector<glm::dvec3>& directions);
  // Records the dispatch for the first `count` directions already in directionBuffer() (benchmarks).
  void record(VkCommandBuffer cmd, uint32_t count) const;
  uint32_t capacity() const { return capacity_; }
  vk::Buffer& directionBuffer() { return directions_; }

 private:
  vk::Device& device_;
  uint32_t capacity_;
  vk::ComputePipeline pipeline_;
  vk::Buffer params_;
  vk::Buffer directions_;
  vk::Buffer heights_;
};

}  // namespace globe
