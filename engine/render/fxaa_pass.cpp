#include "engine/render/fxaa_pass.h"

namespace globe {

namespace {

struct FxaaPush {
  int32_t size[2];  // image width and height (pixels)
};

vk::GraphicsPipelineDesc fxaaDesc() {
  vk::GraphicsPipelineDesc d;
  d.vertexShader = "fullscreen.vert";
  d.fragmentShader = "fxaa.frag";
  d.storageBuffers = 1;  // 0: the scene's texels
  d.pushConstantBytes = sizeof(FxaaPush);
  d.depthFormat = VK_FORMAT_UNDEFINED;  // a colour-only pass
  d.depthTest = false;
  d.depthWrite = false;
  return d;
}

}  // namespace

FxaaPass::FxaaPass(vk::Device& device, VkExtent2D extent)
    : extent_(extent),
      pixels_(device, VkDeviceSize(extent.width) * extent.height * 4,
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::DeviceLocal,
              "FXAA input"),
      pipeline_(device, fxaaDesc()) {}

void FxaaPass::copy(VkCommandBuffer cmd, const vk::Image& scene) const {
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent_.width, extent_.height, 1};
  vkCmdCopyImageToBuffer(cmd, scene.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, pixels_.handle(), 1, &region);
  vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

void FxaaPass::record(VkCommandBuffer cmd) const {
  const FxaaPush push{{int32_t(extent_.width), int32_t(extent_.height)}};
  pipeline_.bind(cmd, {pixels_.descriptor()}, &push, sizeof(push));
  vkCmdDraw(cmd, 3, 1, 0, 0);
}

}  // namespace globe
