#include "engine/vk/compute_pipeline.h"

#include "engine/vk/vk_check.h"

#include <stdexcept>
#include <vector>

namespace globe::vk {

namespace {
VkDescriptorType bufferType(uint32_t binding, uint32_t uniformMask) {
  return (uniformMask >> binding) & 1u ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}
}  // namespace

UniqueDescriptorSetLayout storageBufferSetLayout(Device& device, uint32_t count, VkShaderStageFlags stages,
                                                 uint32_t uniformMask, std::span<const ImageSlot> images) {
  std::vector<VkDescriptorSetLayoutBinding> bindings(count);
  for (uint32_t i = 0; i < count; ++i) bindings[i] = {i, bufferType(i, uniformMask), 1, stages, nullptr};
  for (const ImageSlot& image : images) bindings.push_back({image.binding, image.type, 1, stages, nullptr});
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  info.bindingCount = uint32_t(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout;
  GLOBE_VK_CHECK(vkCreateDescriptorSetLayout(device.device(), &info, nullptr, &layout));
  return UniqueDescriptorSetLayout(device.device(), layout);
}

void pushStorageBuffers(PFN_vkCmdPushDescriptorSetKHR push, VkCommandBuffer cmd, VkPipelineBindPoint bindPoint,
                        VkPipelineLayout layout, std::span<const VkDescriptorBufferInfo> buffers, uint32_t uniformMask,
                        std::span<const ImageDescriptor> images) {
  std::vector<VkWriteDescriptorSet> writes;
  writes.reserve(buffers.size() + images.size());
  uint32_t binding = 0;
  for (const auto& b : buffers) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = binding++;
    w.descriptorCount = 1;
    w.descriptorType = bufferType(w.dstBinding, uniformMask);
    w.pBufferInfo = &b;
    writes.push_back(w);
  }
  for (const ImageDescriptor& image : images) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = image.slot.binding;
    w.descriptorCount = 1;
    w.descriptorType = image.slot.type;
    w.pImageInfo = &image.info;
    writes.push_back(w);
  }
  push(cmd, bindPoint, layout, 0, static_cast<uint32_t>(writes.size()), writes.data());
}

PFN_vkCmdPushDescriptorSetKHR pushDescriptorSetFunction(Device& device) {
  auto push = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(device.device(), "vkCmdPushDescriptorSetKHR"));
  if (!push) throw std::runtime_error("vkCmdPushDescriptorSetKHR is not available");
  return push;
}

UniquePipelineLayout pushDescriptorPipelineLayout(Device& device, VkDescriptorSetLayout setLayout,
                                                  VkShaderStageFlags stages, uint32_t pushConstantBytes) {
  VkPushConstantRange range{stages, 0, pushConstantBytes};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  layoutInfo.pushConstantRangeCount = pushConstantBytes ? 1 : 0;
  layoutInfo.pPushConstantRanges = &range;
  VkPipelineLayout layout;
  GLOBE_VK_CHECK(vkCreatePipelineLayout(device.device(), &layoutInfo, nullptr, &layout));
  return UniquePipelineLayout(device.device(), layout);
}

ComputePipeline::ComputePipeline(Device& device, const std::string& shader, uint32_t buffers,
                                 uint32_t pushConstantBytes, uint32_t uniformMask,
                                 std::span<const uint32_t> specialization, std::span<const ImageSlot> images)
    : device_(device), uniformMask_(uniformMask) {
  pushDescriptorSet_ = pushDescriptorSetFunction(device);
  setLayout_ = storageBufferSetLayout(device, buffers, VK_SHADER_STAGE_COMPUTE_BIT, uniformMask, images);
  layout_ = pushDescriptorPipelineLayout(device, setLayout_, VK_SHADER_STAGE_COMPUTE_BIT, pushConstantBytes);

  UniqueShaderModule module = loadShaderModule(device, shader);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.flags = VK_PIPELINE_CREATE_DISPATCH_BASE_BIT;  // vkCmdDispatchBase (e.g. one payload page at a time)
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  std::vector<VkSpecializationMapEntry> entries(specialization.size());
  for (uint32_t i = 0; i < entries.size(); ++i) entries[i] = {i, i * uint32_t(sizeof(uint32_t)), sizeof(uint32_t)};
  VkSpecializationInfo specializationInfo{static_cast<uint32_t>(entries.size()), entries.data(),
                                          specialization.size_bytes(), specialization.data()};
  if (!specialization.empty()) info.stage.pSpecializationInfo = &specializationInfo;
  info.layout = layout_;
  VkPipeline pipeline;
  GLOBE_VK_CHECK(vkCreateComputePipelines(device.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  pipeline_ = UniquePipeline(device.device(), pipeline);
}

void ComputePipeline::bind(VkCommandBuffer cmd, std::initializer_list<VkDescriptorBufferInfo> buffers,
                           const void* pushConstants, uint32_t pushConstantBytes,
                           std::span<const ImageDescriptor> images) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  pushStorageBuffers(pushDescriptorSet_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_,
                     std::span(buffers.begin(), buffers.size()), uniformMask_, images);
  if (pushConstantBytes)
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes, pushConstants);
}

void computeWriteBarrier(VkCommandBuffer cmd) {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  barrier.srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  barrier.srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  // ALL_COMMANDS excludes the host stage: the host reads results (payload radii) after the fence.
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT | VK_PIPELINE_STAGE_2_HOST_BIT;
  barrier.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_HOST_READ_BIT;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dep);
}

}  // namespace globe::vk
