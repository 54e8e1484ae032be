#include "engine/vk/graphics_pipeline.h"

#include "engine/vk/compute_pipeline.h"
#include "engine/vk/vk_check.h"

#include <algorithm>
#include <stdexcept>

namespace globe::vk {

namespace {

// Premultiplied-alpha "over" when `blend`, else plain writes.
VkPipelineColorBlendAttachmentState colourAttachmentState(bool blend) {
  VkPipelineColorBlendAttachmentState attachment{};
  attachment.colorWriteMask = 0xF;
  if (blend) {
    attachment.blendEnable = VK_TRUE;
    attachment.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
    attachment.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    attachment.colorBlendOp = VK_BLEND_OP_ADD;
    attachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    attachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    attachment.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  return attachment;
}

// The fixed-function state a description asks for. The create info points into it: built in place
// (not copyable) and alive until vkCreateGraphicsPipelines returns.
struct FixedFunctionState {
  explicit FixedFunctionState(const GraphicsPipelineDesc& desc) : attachment(colourAttachmentState(desc.blend)) {
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    raster.polygonMode = desc.wireframe ? VK_POLYGON_MODE_LINE : VK_POLYGON_MODE_FILL;
    raster.cullMode = desc.cull;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    multisample.rasterizationSamples = desc.samples;
    depth.depthTestEnable = desc.depthTest;
    depth.depthWriteEnable = desc.depthWrite;
    depth.depthCompareOp = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reversed-Z
    blend.attachmentCount = 1;
    blend.pAttachments = &attachment;
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamicStates;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &desc.colourFormat;
    rendering.depthAttachmentFormat = desc.depthFormat;
    if (desc.depthOnly) describeDepthOnly(desc);
  }
  void describeDepthOnly(const GraphicsPipelineDesc& desc) {
    depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    raster.depthBiasEnable = desc.depthBiasConstant != 0.0f || desc.depthBiasSlope != 0.0f;
    raster.depthBiasConstantFactor = desc.depthBiasConstant;
    raster.depthBiasSlopeFactor = desc.depthBiasSlope;
    blend.attachmentCount = 0;
    rendering.colorAttachmentCount = 0;
  }
  FixedFunctionState(const FixedFunctionState&) = delete;
  FixedFunctionState& operator=(const FixedFunctionState&) = delete;

  // Fills everything of `info` but the stages and the layout.
  void describe(VkGraphicsPipelineCreateInfo& info) const {
    info.pNext = &rendering;
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
  }

  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  VkPipelineColorBlendAttachmentState attachment;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  VkDynamicState dynamicStates[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
};

}  // namespace

GraphicsPipeline::GraphicsPipeline(Device& device, const GraphicsPipelineDesc& desc) {
  pushDescriptorSet_ = pushDescriptorSetFunction(device);
  uniformMask_ = desc.uniformMask;
  std::vector<ImageSlot> images;
  for (const uint32_t binding : desc.sampledImageBindings) images.push_back({binding});
  setLayout_ = storageBufferSetLayout(device, desc.storageBuffers, stages_, desc.uniformMask, images);
  layout_ = pushDescriptorPipelineLayout(device, setLayout_, stages_, desc.pushConstantBytes);

  UniqueShaderModule vert = loadShaderModule(device, desc.vertexShader);
  UniqueShaderModule frag;
  if (!desc.depthOnly) frag = loadShaderModule(device, desc.fragmentShader);
  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vert;
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = frag;
  stages[1].pName = "main";
  // constant_id k of a stage takes its vector's [k].
  const size_t most = std::max(desc.vertexSpecialization.size(), desc.fragmentSpecialization.size());
  std::vector<VkSpecializationMapEntry> entries(most);
  for (uint32_t k = 0; k < entries.size(); ++k) entries[k] = {k, k * uint32_t(sizeof(uint32_t)), sizeof(uint32_t)};
  const VkSpecializationInfo vertexSpecialization{uint32_t(desc.vertexSpecialization.size()), entries.data(),
                                                  desc.vertexSpecialization.size() * sizeof(uint32_t),
                                                  desc.vertexSpecialization.data()};
  const VkSpecializationInfo fragmentSpecialization{uint32_t(desc.fragmentSpecialization.size()), entries.data(),
                                                    desc.fragmentSpecialization.size() * sizeof(uint32_t),
                                                    desc.fragmentSpecialization.data()};
  if (!desc.vertexSpecialization.empty()) stages[0].pSpecializationInfo = &vertexSpecialization;
  if (!desc.fragmentSpecialization.empty()) stages[1].pSpecializationInfo = &fragmentSpecialization;

  FixedFunctionState state(desc);
  if (desc.depthOnly) {
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(device.physical(), &features);
    state.raster.depthClampEnable = features.depthClamp;
  }
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  state.describe(info);
  info.stageCount = desc.depthOnly ? 1 : 2;
  info.pStages = stages;
  info.layout = layout_;
  VkPipeline pipeline;
  GLOBE_VK_CHECK(vkCreateGraphicsPipelines(device.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  pipeline_ = UniquePipeline(device.device(), pipeline);
}

void GraphicsPipeline::bind(VkCommandBuffer cmd, std::span<const VkDescriptorBufferInfo> buffers,
                            const void* pushConstants, uint32_t pushConstantBytes,
                            std::span<const ImageDescriptor> images) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  if (buffers.size() || images.size())
    pushStorageBuffers(pushDescriptorSet_, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, buffers, uniformMask_,
                       images);
  if (pushConstantBytes) vkCmdPushConstants(cmd, layout_, stages_, 0, pushConstantBytes, pushConstants);
}

}  // namespace globe::vk
