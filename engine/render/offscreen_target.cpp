#include "engine/render/offscreen_target.h"

#include "shaders/include/display_encoding.h"

#include <array>
#include <cmath>
#include <tuple>

#include <stdexcept>

namespace globe {

Status checkImageExtent(const vk::Device& device, VkExtent2D extent, const std::string& field) {
  const uint32_t limit = device.properties().limits.maxImageDimension2D;
  if (extent.width <= limit && extent.height <= limit) return Ok{};
  return Error::inField(field, std::to_string(extent.width) + "x" + std::to_string(extent.height) + " is larger than " +
                                   device.name() + " makes images (maxImageDimension2D " + std::to_string(limit) + ")");
}

namespace {
VkExtent2D checkedExtent(const vk::Device& device, VkExtent2D extent) {
  if (auto s = checkImageExtent(device, extent, "image size"); !s) throw std::runtime_error(s.error().format());
  return extent;
}

// Linear colour of each stored 8-bit code: the exact inverse of display_encoding.glsl.
const std::array<float, 256>& linearOfCode() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    const double a = GLOBE_DISPLAY_ENCODING_A;
    for (int code = 0; code < 256; ++code) {
      const double e = code / 255.0;
      const double root = (a - std::sqrt(std::max(a * a - 4.0 * (a - 1.0) * e, 0.0))) / (2.0 * (a - 1.0));
      t[size_t(code)] = float(root * root);
    }
    return t;
  }();
  return table;
}
}  // namespace

void setWholeViewport(VkCommandBuffer cmd, VkExtent2D extent) {
  VkViewport viewport{0, 0, float(extent.width), float(extent.height), 0, 1};
  VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

OffscreenTarget::OffscreenTarget(vk::Device& device, VkExtent2D extent, Antialiasing antialiasing)
    : device_(device),
      colour_(device, kColourFormat, checkedExtent(device, extent),
              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT,
              "offscreen colour"),
      depth_(device, kDepthFormat, extent,
             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_DEPTH_BIT,
             "offscreen depth"),
      antialiasing_(antialiasing),
      colourReadback_(device, VkDeviceSize(extent.width) * extent.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      vk::MemoryUse::HostVisible, "colour readback"),
      depthReadback_(device, VkDeviceSize(extent.width) * extent.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                     vk::MemoryUse::HostVisible, "depth readback") {
  if (antialiasing_ == Antialiasing::kFxaa) {
    fxaaInput_ =
        vk::Image(device, kColourFormat, extent, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                  VK_IMAGE_ASPECT_COLOR_BIT, "offscreen colour (before FXAA)");
    fxaa_ = std::make_unique<FxaaPass>(device, extent);
  }
  if (antialiasing_ != Antialiasing::kMsaa4) return;
  // Transient: only the resolved images outlive the pass.
  multisampledColour_ = vk::Image(device, kColourFormat, extent,
                                  VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                                  VK_IMAGE_ASPECT_COLOR_BIT, "offscreen colour (multisampled)", samples());
  multisampledDepth_ = vk::Image(device, kDepthFormat, extent,
                                 VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                                 VK_IMAGE_ASPECT_DEPTH_BIT, "offscreen depth (multisampled)", samples());
}

void OffscreenTarget::begin(VkCommandBuffer cmd, const float clear[4]) {
  VkImageLayout colourFrom = initialised_ ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
  vk::transitionImage(cmd, colour_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, colourFrom,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  vk::transitionImage(
      cmd, depth_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT,
      colourFrom == VK_IMAGE_LAYOUT_UNDEFINED ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
      VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
  initialised_ = true;

  VkRenderingAttachmentInfo colour{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  colour.imageView = colour_.view();
  colour.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  colour.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  for (int i = 0; i < 4; ++i) colour.clearValue.color.float32[i] = clear[i];
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = depth_.view();
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth.clearValue.depthStencil = {0.0f, 0};  // reversed-Z: far is 0
  if (antialiasing_ == Antialiasing::kMsaa4) drawMultisampled(cmd, colour, depth);
  if (fxaa_) {
    vk::transitionImage(cmd, fxaaInput_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    colour.imageView = fxaaInput_.view();
  }
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, extent()};
  info.layerCount = 1;
  info.colorAttachmentCount = 1;
  info.pColorAttachments = &colour;
  info.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &info);
  setWholeViewport(cmd, extent());
}

void OffscreenTarget::drawMultisampled(VkCommandBuffer cmd, VkRenderingAttachmentInfo& colour,
                                       VkRenderingAttachmentInfo& depth) {
  // Cleared every frame: the previous contents are not needed.
  vk::transitionImage(cmd, multisampledColour_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  vk::transitionImage(cmd, multisampledDepth_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
  for (auto [attachment, image, mode] : {std::tuple{&colour, &multisampledColour_, VK_RESOLVE_MODE_AVERAGE_BIT},
                                         std::tuple{&depth, &multisampledDepth_, VK_RESOLVE_MODE_SAMPLE_ZERO_BIT}}) {
    attachment->resolveMode = mode;  // SAMPLE_ZERO: the depth resolve every device supports
    attachment->resolveImageView = attachment->imageView;
    attachment->resolveImageLayout = attachment->imageLayout;
    attachment->imageView = image->view();
    attachment->storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  }
}

void OffscreenTarget::filter(VkCommandBuffer cmd) {
  vk::transitionImage(cmd, fxaaInput_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  fxaa_->copy(cmd, fxaaInput_);
  VkRenderingAttachmentInfo colour{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  colour.imageView = colour_.view();
  colour.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  colour.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // every pixel is written
  colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, extent()};
  info.layerCount = 1;
  info.colorAttachmentCount = 1;
  info.pColorAttachments = &colour;
  vkCmdBeginRendering(cmd, &info);
  setWholeViewport(cmd, extent());
  fxaa_->record(cmd);
  vkCmdEndRendering(cmd);
}

void OffscreenTarget::end(VkCommandBuffer cmd) {
  vkCmdEndRendering(cmd);
  if (fxaa_) filter(cmd);
  vk::transitionImage(cmd, colour_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  vk::transitionImage(cmd, depth_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
}

ReadbackImage OffscreenTarget::readback() {
  VkExtent2D e = extent();
  device_.submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {e.width, e.height, 1};
    vkCmdCopyImageToBuffer(cmd, colour_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colourReadback_.handle(), 1,
                           &region);
    region.imageSubresource.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    vkCmdCopyImageToBuffer(cmd, depth_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, depthReadback_.handle(), 1,
                           &region);
    vk::hostReadBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  });
  ReadbackImage out;
  out.width = e.width;
  out.height = e.height;
  size_t n = size_t(e.width) * e.height;
  out.rgba.resize(n * 4);
  static_assert(kColourFormat == VK_FORMAT_B8G8R8A8_UNORM, "the decode below reads B, G, R, A bytes");
  const auto* bgra = static_cast<const uint8_t*>(colourReadback_.mapped());
  const std::array<float, 256>& linear = linearOfCode();
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = bgra + 4 * i;
    out.rgba[4 * i + 0] = linear[p[2]];
    out.rgba[4 * i + 1] = linear[p[1]];
    out.rgba[4 * i + 2] = linear[p[0]];
    out.rgba[4 * i + 3] = float(p[3]) / 255.0f;
  }
  const auto* depths = static_cast<const float*>(depthReadback_.mapped());
  out.depth.assign(depths, depths + n);
  return out;
}

}  // namespace globe
