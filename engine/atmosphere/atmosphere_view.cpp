#include "engine/atmosphere/atmosphere_view.h"

#include <cmath>
#include <cstring>

namespace globe {
namespace {

// The camera block, then the table (minStorageBufferOffsetAlignment is at most 256).
constexpr VkDeviceSize kCameraBytes = 256;
constexpr VkDeviceSize kTableBytes = VkDeviceSize(GLOBE_VIEW_TEXELS + 2) * 16;
static_assert(sizeof(gpu::AtmosphereViewGpu) <= kCameraBytes);

gpu::AtmosphereVec4 vec4(const glm::dvec3& v, double w) { return {float(v.x), float(v.y), float(v.z), float(w)}; }

}  // namespace

AtmosphereView::AtmosphereView(vk::Device& device, const AtmosphereLuts& luts)
    : luts_(luts), pipeline_(device, "atmosphere_view.comp", 6, 0, (1u << 0) | (1u << 4)) {
  for (uint32_t f = 0; f < vk::kFramesInFlight; ++f) {
    frames_[f] = vk::Buffer(device, kCameraBytes + kTableBytes,
                            VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                            vk::MemoryUse::HostVisible, f == 0 ? "atmosphere view 0" : "atmosphere view 1");
  }
}

void AtmosphereView::record(VkCommandBuffer cmd, const Camera& camera, const glm::dvec3& sun,
                            const glm::dvec2& terrainRadii_m, uint32_t frameIndex) {
  const double tanY = std::tan(camera.verticalFov_rad * 0.5);
  const gpu::AtmosphereViewGpu block{vec4(camera.position_m, 0.0),
                                     vec4(glm::normalize(sun), 0.0),
                                     vec4(camera.right, tanY * camera.aspect),
                                     vec4(camera.up, tanY),
                                     vec4(camera.forward, 0.0),
                                     {float(terrainRadii_m.x), float(terrainRadii_m.y), 0.0f, 0.0f}};
  std::memcpy(frames_[frameIndex].mapped(), &block, sizeof(block));
  pipeline_.bind(cmd,
                 {luts_.parameters(), luts_.transmittance(), luts_.irradiance(), luts_.scattering(),
                  this->camera(frameIndex), table(frameIndex)},
                 nullptr, 0);
  vkCmdDispatch(cmd, (GLOBE_VIEW_TEXELS + 2 + 63) / 64, 1, 1);
  vk::computeWriteBarrier(cmd);
}

VkDescriptorBufferInfo AtmosphereView::camera(uint32_t frameIndex) const {
  return {frames_[frameIndex].handle(), 0, sizeof(gpu::AtmosphereViewGpu)};
}

VkDescriptorBufferInfo AtmosphereView::table(uint32_t frameIndex) const {
  return {frames_[frameIndex].handle(), kCameraBytes, kTableBytes};
}

const uint32_t* AtmosphereView::tableData(uint32_t frameIndex) const {
  return reinterpret_cast<const uint32_t*>(static_cast<const unsigned char*>(frames_[frameIndex].mapped()) +
                                           kCameraBytes);
}

}  // namespace globe
