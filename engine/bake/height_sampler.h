#pragma once
// Where a bake's heights come from: the GPU kernel the renderer's payloads share
// (shaders/include/elevation.glsl, through ElevationSampler) in batches, or the CPU reference
// (ElevationModel) it is tested against. A planet with [[sources]] gets each sample's source term
// from the CPU (sourceTermsAt, the payloads' own path: tiles read through the sources' tile cache
// on the calling threads) and the kernel blends it over the procedural layers.
#include "engine/generation/elevation_sampler.h"
#include "planet/model/elevation_model.h"

#include <memory>
#include <vector>

#include <glm/vec3.hpp>

namespace globe {

class HeightSampler {
 public:
  virtual ~HeightSampler() = default;
  // Elevation above radius_m (metres) at each unit direction.
  virtual std::vector<double> heights_m(const std::vector<glm::dvec3>& directions) = 0;
};

class GpuHeightSampler final : public HeightSampler {
 public:
  static constexpr std::uint32_t kBatchDirections = 1u << 18;  // 10 MiB of buffers
  // `threads`: CPU threads resolving the source terms (a planet with sources).
  GpuHeightSampler(vk::Device& device, const ElevationModel& model, unsigned threads = 1);
  std::vector<double> heights_m(const std::vector<glm::dvec3>& directions) override;

 private:
  const ElevationModel& model_;
  unsigned threads_;
  ElevationSampler sampler_;
};

class CpuHeightSampler final : public HeightSampler {
 public:
  CpuHeightSampler(const ElevationModel& model, unsigned threads) : model_(model), threads_(threads) {}
  std::vector<double> heights_m(const std::vector<glm::dvec3>& directions) override;

 private:
  const ElevationModel& model_;
  unsigned threads_;
};

}  // namespace globe
