#pragma once
// A graphics pipeline for dynamic rendering into the offscreen (or swapchain) formats: no vertex
// input (vertex shaders pull from storage buffers), reversed-Z depth test, push constants and
// storage buffers pushed per draw.
#include "engine/vk/compute_pipeline.h"
#include "engine/vk/resources.h"

#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace globe::vk {

// The scene's colour format: 8-bit UNORM holding the display encoding of shaders/include/
// display_encoding.h (lavapipe stores it cheaper than sRGB or half float), blue first like the
// swapchains of most surfaces so the viewer's blit is a plain copy.
inline constexpr VkFormat kSceneColourFormat = VK_FORMAT_B8G8R8A8_UNORM;

struct GraphicsPipelineDesc {
  std::string vertexShader;     // e.g. "terrain.vert"
  std::string fragmentShader;   // e.g. "terrain.frag"
  uint32_t storageBuffers = 0;  // buffer bindings 0..n-1 (storage, or uniform per uniformMask)
  uint32_t uniformMask = 0;     // bit b: binding b is a uniform buffer (see compute_pipeline.h)
  uint32_t pushConstantBytes = 0;
  VkFormat colourFormat = kSceneColourFormat;
  VkFormat depthFormat = VK_FORMAT_D32_SFLOAT;
  bool depthTest = true;  // reversed-Z: GREATER_OR_EQUAL passes nearer fragments
  bool depthWrite = true;
  // A depth-only pipeline (shadow maps): no fragment stage, no colour attachment (colourFormat is
  // ignored), forward depth (LESS_OR_EQUAL passes fragments nearer the light), and the rasteriser's
  // depth bias (constant, slope factors); depth clamped where the device has depthClamp.
  bool depthOnly = false;
  float depthBiasConstant = 0.0f;
  float depthBiasSlope = 0.0f;
  bool wireframe = false;  // needs fillModeNonSolid
  VkCullModeFlags cull = VK_CULL_MODE_NONE;
  bool blend = false;                                     // premultiplied-alpha blending (overlays)
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  // the target's (OffscreenTarget::samples)
  // Specialization constants of the fragment shader: constant_id k takes fragmentSpecialization[k].
  std::vector<uint32_t> fragmentSpecialization;
  std::vector<uint32_t> vertexSpecialization;  // the same for the vertex shader
  // Bindings of combined image samplers after the buffers; bind() pushes them.
  std::vector<uint32_t> sampledImageBindings;
};

class GraphicsPipeline {
 public:
  GraphicsPipeline(Device& device, const GraphicsPipelineDesc& desc);

  // `images`: what the sampledImageBindings hold (all of them, or none when no shader reads them).
  void bind(VkCommandBuffer cmd, std::initializer_list<VkDescriptorBufferInfo> buffers, const void* pushConstants,
            uint32_t pushConstantBytes, std::span<const ImageDescriptor> images = {}) const {
    bind(cmd, std::span(buffers.begin(), buffers.size()), pushConstants, pushConstantBytes, images);
  }
  // The same with buffers 0..n-1 gathered at run time.
  void bind(VkCommandBuffer cmd, std::span<const VkDescriptorBufferInfo> buffers, const void* pushConstants,
            uint32_t pushConstantBytes, std::span<const ImageDescriptor> images = {}) const;

  VkPipeline pipeline() const { return pipeline_; }
  VkPipelineLayout layout() const { return layout_; }

 private:
  UniqueDescriptorSetLayout setLayout_;
  UniquePipelineLayout layout_;
  UniquePipeline pipeline_;
  PFN_vkCmdPushDescriptorSetKHR pushDescriptorSet_ = nullptr;
  uint32_t uniformMask_ = 0;
  VkShaderStageFlags stages_ = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
};

}  // namespace globe::vk
