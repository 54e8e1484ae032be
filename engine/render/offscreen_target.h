#pragma once
// An offscreen render target: display-encoded 8-bit colour (vk::kSceneColourFormat) and a 32-bit float
// depth buffer (reversed-Z: 1 is near, 0 is infinitely far), with readback to linear floats.
// Anti-aliased (antialiasing.h): with MSAA x4 the pass draws into multisampled colour and depth images
// and resolves them at its end into the one-sample images that are read back or copied: colour
// averaged, depth from sample 0 (at the standard location, not the pixel centre). With FXAA it draws
// into an intermediate colour image that end() filters into the colour image; depth as without.
#include "engine/render/antialiasing.h"
#include "engine/render/fxaa_pass.h"
#include "engine/vk/graphics_pipeline.h"
#include "engine/vk/resources.h"
#include "planet/core/error.h"

#include <memory>
#include <string>
#include <vector>

namespace globe {

// What a frame looks like on the CPU after readback.
struct ReadbackImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgba;   // linear colour, 4 floats per pixel, row 0 at the top
  std::vector<float> depth;  // device depth per pixel (reversed-Z: 0 = nothing drawn / infinity)

  float depthAt(uint32_t x, uint32_t y) const { return depth[size_t(y) * width + x]; }
  const float* pixel(uint32_t x, uint32_t y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

// The device can make 2D images this large (VkPhysicalDeviceLimits::maxImageDimension2D); the
// one-line Error names `field` (the command's --size) and the limit. Checked before anything is
// allocated: the OffscreenTarget constructor throws it as std::runtime_error.
Status checkImageExtent(const vk::Device& device, VkExtent2D extent, const std::string& field);

class OffscreenTarget {
 public:
  static constexpr VkFormat kColourFormat = vk::kSceneColourFormat;
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

  OffscreenTarget(vk::Device& device, VkExtent2D extent, Antialiasing antialiasing = Antialiasing::kNone);

  VkExtent2D extent() const { return colour_.extent(); }
  // Samples per pixel of the pass: every pipeline drawing into it must have as many.
  VkSampleCountFlagBits samples() const { return sampleCount(antialiasing_); }
  Antialiasing antialiasing() const { return antialiasing_; }
  const vk::Image& colour() const { return colour_; }
  const vk::Image& depth() const { return depth_; }

  // Layout expected by begin(): images are kept in attachment layouts between frames.
  // Records vkCmdBeginRendering with clear colour `clear` (linear RGBA) and depth 0 (reversed-Z).
  void begin(VkCommandBuffer cmd, const float clear[4]);
  void end(VkCommandBuffer cmd);

  // Copies colour and depth to the CPU (submits and waits).
  ReadbackImage readback();

 private:
  // Points `colour` and `depth` at the multisampled images, resolving into the one-sample ones.
  void drawMultisampled(VkCommandBuffer cmd, VkRenderingAttachmentInfo& colour, VkRenderingAttachmentInfo& depth);
  // FXAA: the second pass, fxaaInput_ into colour_.
  void filter(VkCommandBuffer cmd);

  vk::Device& device_;
  vk::Image colour_;
  vk::Image depth_;
  Antialiasing antialiasing_;
  vk::Image multisampledColour_;  // MSAA only: what the pass draws into
  vk::Image multisampledDepth_;
  vk::Image fxaaInput_;  // FXAA only: what the pass draws into, then end() filters into colour_
  std::unique_ptr<FxaaPass> fxaa_;
  vk::Buffer colourReadback_;
  vk::Buffer depthReadback_;
  bool initialised_ = false;
};

// Viewport and scissor over the whole of `extent` (depth 0..1).
void setWholeViewport(VkCommandBuffer cmd, VkExtent2D extent);

}  // namespace globe
