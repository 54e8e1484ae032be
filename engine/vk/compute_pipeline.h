#pragma once
// A compute pipeline whose bindings are buffers pushed per dispatch (VK_KHR_push_descriptor) plus a
// push-constant block. Enough for every generation kernel. Bindings are storage buffers, except
// those in `uniformMask` (bit b: binding b is a uniform buffer) — small read-only parameter blocks
// that every invocation reads, which lavapipe fetches with one load instead of per-lane gathers
// (measured 1.4x on the elevation kernel, docs/elevation.md).
#include "engine/vk/resources.h"

#include <initializer_list>
#include <span>
#include <string>

namespace globe::vk {

class ComputePipeline {
 public:
  // `shader` names a compiled shader ("payload.comp"); `buffers` bindings 0..n-1. `specialization`
  // gives 32-bit specialization constant i the value specialization[i].
  ComputePipeline(Device& device, const std::string& shader, uint32_t buffers, uint32_t pushConstantBytes,
                  uint32_t uniformMask = 0, std::span<const uint32_t> specialization = {});

  // Binds the pipeline, pushes the buffers as bindings 0..n-1 and the push constants.
  void bind(VkCommandBuffer cmd, std::initializer_list<VkDescriptorBufferInfo> buffers, const void* pushConstants,
            uint32_t pushConstantBytes) const;

  VkPipeline pipeline() const { return pipeline_; }
  VkPipelineLayout layout() const { return layout_; }

 private:
  Device& device_;
  UniqueDescriptorSetLayout setLayout_;
  UniquePipelineLayout layout_;
  UniquePipeline pipeline_;
  PFN_vkCmdPushDescriptorSetKHR pushDescriptorSet_ = nullptr;
  uint32_t uniformMask_ = 0;
};

// A combined image sampler pushed with the buffers, at its own binding (past the buffers').
inline constexpr uint32_t kNoSampledImage = ~0u;
struct SampledImage {
  uint32_t binding = kNoSampledImage;
  VkDescriptorImageInfo info{};
};

// Pushes `buffers` as bindings 0..n-1 of set 0 (shared by compute and graphics); bindings in
// `uniformMask` are uniform buffers, the others storage buffers; and `image` if not null.
void pushStorageBuffers(PFN_vkCmdPushDescriptorSetKHR push, VkCommandBuffer cmd, VkPipelineBindPoint bindPoint,
                        VkPipelineLayout layout, std::span<const VkDescriptorBufferInfo> buffers,
                        uint32_t uniformMask = 0, const SampledImage* image = nullptr);

// A push-descriptor set layout with `count` buffers visible to `stages` (uniform where `uniformMask`
// has the binding's bit, storage otherwise), and a combined image sampler at `sampledImageBinding`.
UniqueDescriptorSetLayout storageBufferSetLayout(Device& device, uint32_t count, VkShaderStageFlags stages,
                                                 uint32_t uniformMask = 0,
                                                 uint32_t sampledImageBinding = kNoSampledImage);

// vkCmdPushDescriptorSetKHR of `device` (throws when the extension's entry point is missing).
PFN_vkCmdPushDescriptorSetKHR pushDescriptorSetFunction(Device& device);

// A pipeline layout of one push-descriptor set and, when pushConstantBytes > 0, one push-constant
// range visible to `stages`.
UniquePipelineLayout pushDescriptorPipelineLayout(Device& device, VkDescriptorSetLayout setLayout,
                                                  VkShaderStageFlags stages, uint32_t pushConstantBytes);

// A memory barrier making compute-shader writes visible to later reads (vertex, transfer, host...).
void computeWriteBarrier(VkCommandBuffer cmd);

}  // namespace globe::vk
