#include "engine/vk/fxaa_pass.h"

#include "engine/vk/vk_check.h"

namespace globe::vk {

namespace {

struct FxaaPush {
  float texel[2];  // 1 / image size (width, height)
};

// Bilinear and clamped: FXAA reads between pixels, and never beyond the border.
UniqueSampler linearClampSampler(Device& device) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxLod = 0.0f;
  VkSampler sampler;
  GLOBE_VK_CHECK(vkCreateSampler(device.device(), &info, nullptr, &sampler));
  return UniqueSampler(device.device(), sampler);
}

GraphicsPipelineDesc fxaaDesc() {
  GraphicsPipelineDesc d;
  d.vertexShader = "fullscreen.vert";
  d.fragmentShader = "fxaa.frag";
  d.pushConstantBytes = sizeof(FxaaPush);
  d.depthFormat = VK_FORMAT_UNDEFINED;  // a colour-only pass
  d.depthTest = false;
  d.depthWrite = false;
  d.sampledImage = true;
  return d;
}

}  // namespace

FxaaPass::FxaaPass(Device& device) : sampler_(linearClampSampler(device)), pipeline_(device, fxaaDesc()) {}

void FxaaPass::record(VkCommandBuffer cmd, const Image& scene) const {
  const FxaaPush push{{1.0f / float(scene.extent().width), 1.0f / float(scene.extent().height)}};
  pipeline_.bindImage(cmd, {sampler_, scene.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}, &push, sizeof(push));
  vkCmdDraw(cmd, 3, 1, 0, 0);
}

}  // namespace globe::vk
