#pragma once
// A compute pipeline whose bindings are storage buffers pushed per dispatch
// (VK_KHR_push_descriptor) plus a push-constant block. Enough for every generation kernel.
#include "engine/resources.h"

#include <initializer_list>
#include <string>

namespace globe::vk {

class ComputePipeline {
 public:
  // `shader` names a compiled shader ("payload.comp"); `storageBuffers` bindings 0..n-1.
  ComputePipeline(Device& device, const std::string& shader, uint32_t storageBuffers, uint32_t pushConstantBytes);

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
};

// Pushes `buffers` as storage-buffer bindings 0..n-1 of set 0 (shared by compute and graphics).
void pushStorageBuffers(PFN_vkCmdPushDescriptorSetKHR push, VkCommandBuffer cmd, VkPipelineBindPoint bindPoint,
                        VkPipelineLayout layout, std::initializer_list<VkDescriptorBufferInfo> buffers);

// A push-descriptor set layout with `count` storage buffers visible to `stages`.
UniqueDescriptorSetLayout storageBufferSetLayout(Device& device, uint32_t count, VkShaderStageFlags stages);

// A memory barrier making compute-shader writes visible to later reads (vertex, transfer, host...).
void computeWriteBarrier(VkCommandBuffer cmd);

}  // namespace globe::vk
