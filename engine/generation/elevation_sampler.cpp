#include "engine/generation/elevation_sampler.h"

#include "engine/vk/vk_check.h"

#include <array>
#include <cassert>
#include <cstring>
#include <stdexcept>

namespace globe {

ElevationSampler::ElevationSampler(vk::Device& device, const gpu::ElevationParams& params, uint32_t capacity,
                                   bool withSourceTerms)
    : device_(device),
      capacity_(capacity),
      pipeline_(device, "elevation_samples.comp", 4, sizeof(uint32_t), /*uniformMask=*/1u,
                elevationSpecialization(params)),
      params_(device, sizeof(gpu::ElevationParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::HostVisible,
              "elevation params"),
      directions_(device, VkDeviceSize(capacity) * 32, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible,
                  "sample directions"),
      heights_(device, VkDeviceSize(capacity) * 8, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible,
               "sample heights"),
      terms_(device, withSourceTerms ? VkDeviceSize(capacity) * 32 : 32, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
             vk::MemoryUse::HostVisible, "sample source terms") {
  std::memcpy(params_.mapped(), &params, sizeof(params));
}

void ElevationSampler::record(VkCommandBuffer cmd, uint32_t count) const {
  pipeline_.bind(cmd, {params_.descriptor(), directions_.descriptor(), heights_.descriptor(), terms_.descriptor()},
                 &count, sizeof(count));
  vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
  vk::computeWriteBarrier(cmd);
}

std::vector<double> ElevationSampler::sample(const std::vector<glm::dvec3>& directions,
                                             std::span<const glm::dvec4> terms) {
  assert(directions.size() <= capacity_);
  auto count = static_cast<uint32_t>(directions.size());
  if (!terms.empty() && (terms.size() != directions.size() || terms_.size() < VkDeviceSize(count) * 32))
    throw std::invalid_argument("ElevationSampler: one source term per direction, within the capacity");
  auto d = directions_.as<double>();
  for (uint32_t i = 0; i < count; ++i) {
    d[i * 4 + 0] = directions[i].x;
    d[i * 4 + 1] = directions[i].y;
    d[i * 4 + 2] = directions[i].z;
    d[i * 4 + 3] = terms.empty() ? 0.0 : 1.0;
  }
  if (!terms.empty()) std::memcpy(terms_.mapped(), terms.data(), terms.size_bytes());
  device_.submitAndWait([&](VkCommandBuffer cmd) { record(cmd, count); });
  auto h = heights_.as<double>();
  return {h.begin(), h.begin() + count};
}

}  // namespace globe
