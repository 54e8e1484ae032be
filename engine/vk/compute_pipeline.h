#pragma once
// A compute pipeline whose bindings are buffers (and storage images) pushed per dispatch
// (VK_KHR_push_descriptor) plus a push-constant block. Enough for every generation kernel. Bindings are storage
// buffers, except those in `uniformMask` (bit b: binding b is a uniform buffer) — small read-only parameter blocks that
// every invocation reads, which lavapipe fetches with one load instead of per-lane gathers (measured 1.4x on the
// elevation kernel, docs/elevation.md).
#include "engine/vk/resources.h"

#include <initializer_list>
#include <span>
#include <string>

namespace globe::vk {

// An image binding of a push-descriptor set, past the buffers': a combined image sampler (sampled
// with the sampler's filtering) or a storage image (written by a kernel).
struct ImageSlot {
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
};
// What one image binding holds for a draw or dispatch.
struct ImageDescriptor {
  ImageSlot slot;
  VkDescriptorImageInfo info{};
};

class ComputePipeline {
 public:
  // `shader` names a compiled shader ("payload.comp"); `buffers` bindings 0..n-1. `specialization`
  // gives 32-bit specialization constant i the value specialization[i]; `images` the image bindings.
  ComputePipeline(Device& device, const std::string& shader, uint32_t buffers, uint32_t pushConstantBytes,
                  uint32_t uniformMask = 0, std::span<const uint32_t> specialization = {},
                  std::span<const ImageSlot> images = {});

  // Binds the pipeline, pushes the buffers as bindings 0..n-1, the images and the push constants.
  void bind(VkCommandBuffer cmd, std::initializer_list<VkDescriptorBufferInfo> buffers, const void* pushConstants,
            uint32_t pushConstantBytes, std::span<const ImageDescriptor> images = {}) const;

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

// Pushes `buffers` as bindings 0..n-1 of set 0 (shared by compute and graphics); bindings in
// `uniformMask` are uniform buffers, the others storage buffers; and `images`.
void pushStorageBuffers(PFN_vkCmdPushDescriptorSetKHR push, VkCommandBuffer cmd, VkPipelineBindPoint bindPoint,
                        VkPipelineLayout layout, std::span<const VkDescriptorBufferInfo> buffers,
                        uint32_t uniformMask = 0, std::span<const ImageDescriptor> images = {});

// A push-descriptor set layout with `count` buffers visible to `stages` (uniform where `uniformMask`
// has the binding's bit, storage otherwise), and the image bindings `images`.
UniqueDescriptorSetLayout storageBufferSetLayout(Device& device, uint32_t count, VkShaderStageFlags stages,
                                                 uint32_t uniformMask = 0, std::span<const ImageSlot> images = {});

// vkCmdPushDescriptorSetKHR of `device` (throws when the extension's entry point is missing).
PFN_vkCmdPushDescriptorSetKHR pushDescriptorSetFunction(Device& device);

// A pipeline layout of one push-descriptor set and, when pushConstantBytes > 0, one push-constant
// range visible to `stages`.
UniquePipelineLayout pushDescriptorPipelineLayout(Device& device, VkDescriptorSetLayout setLayout,
                                                  VkShaderStageFlags stages, uint32_t pushConstantBytes);

// A memory barrier making compute-shader writes visible to later reads (vertex, transfer, host...).
void computeWriteBarrier(VkCommandBuffer cmd);

}  // namespace globe::vk
