#include "engine/bake/height_sampler.h"

#include "planet/core/parallel_for.h"
#include "planet/streaming/request_preparer.h"

#include <algorithm>

namespace globe {

GpuHeightSampler::GpuHeightSampler(vk::Device& device, const ElevationModel& model, unsigned threads)
    : model_(model),
      threads_(threads),
      sampler_(device, model.params(), kBatchDirections, model.sources() != nullptr) {}

std::vector<double> GpuHeightSampler::heights_m(const std::vector<glm::dvec3>& directions) {
  std::vector<double> out;
  out.reserve(directions.size());
  std::vector<glm::dvec3> batch;
  for (std::size_t first = 0; first < directions.size(); first += kBatchDirections) {
    const std::size_t last = std::min(directions.size(), first + kBatchDirections);
    batch.assign(directions.begin() + std::ptrdiff_t(first), directions.begin() + std::ptrdiff_t(last));
    const std::vector<glm::dvec4> terms = sourceTermsAt(model_, batch, threads_);
    const std::vector<double> h = sampler_.sample(batch, terms);
    out.insert(out.end(), h.begin(), h.end());
  }
  return out;
}

std::vector<double> CpuHeightSampler::heights_m(const std::vector<glm::dvec3>& directions) {
  std::vector<double> out(directions.size());
  parallelFor(directions.size(), 4096, threads_, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) out[k] = model_.elevation_m(directions[k]);
  });
  return out;
}

}  // namespace globe
