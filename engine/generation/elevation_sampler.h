#pragma once
// Evaluates the elevation function on the GPU, in double, at many directions at once. Used to
// test the shader against the CPU reference and to measure samples per second; terrain payloads
// use the same include (shaders/include/elevation.glsl) from their own kernel. The parameters are
// bound as a uniform buffer (binding 0), the directions and heights as storage buffers. A planet
// with [[sources]] passes each direction's source term (sourceTermsAt, planet/sources/
// request_preparer.h), which the kernel blends as the payload kernel does (elevation_sources.glsl).
#include "engine/vk/compute_pipeline.h"
#include "planet/model/elevation_model.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

namespace globe {

class ElevationSampler {
 public:
  // `withSourceTerms`: room for one source term per direction (else a 32-byte dummy is bound).
  ElevationSampler(vk::Device& device, const gpu::ElevationParams& params, uint32_t capacity,
                   bool withSourceTerms = false);

  // Elevation (metres above radius) at each unit direction; at most capacity() per call. `terms`
  // is empty (the procedural layers only) or one packed source term per direction.
  std::vector<double> sample(const std::vector<glm::dvec3>& directions, std::span<const glm::dvec4> terms = {});
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
  vk::Buffer terms_;
};

}  // namespace globe
