#include "engine/render/terrain_shadows.h"

#include "engine/render/offscreen_target.h"
#include "engine/render/terrain_instance.h"
#include "engine/vk/vk_check.h"
#include "planet/lod/lod_ranges.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace globe {
namespace {

constexpr VkFormat kShadowFormat = VK_FORMAT_D32_SFLOAT;
// Per-frame buffer: each cascade's frame constants at a uniform-buffer offset every device accepts,
// then the instances.
constexpr VkDeviceSize kCascadeFrameBytes = 768;
constexpr VkDeviceSize kHeaderBytes = kCascadeFrameBytes * kShadowCascades;
static_assert(sizeof(gpu::TerrainFrame) <= kCascadeFrameBytes);
constexpr uint32_t kGrids = 2;  // full and half grid

// Depth bias of the shadow pass, in the rasteriser's units: slope-scaled, so that a surface lit at a
// grazing angle (its depth changing fast across a texel) clears its own depth.
constexpr float kBiasSlope = 2.0f;
constexpr float kBiasConstant = 0.0f;

vk::GraphicsPipelineDesc shadowDesc() {
  vk::GraphicsPipelineDesc d;
  d.vertexShader = "terrain_shadow.vert";
  d.storageBuffers = 3;  // 0: instances, 1: payloads, 2: the cascade's frame constants (uniform)
  d.uniformMask = 1u << 2;
  d.pushConstantBytes = sizeof(gpu::TerrainDrawPush);
  d.depthFormat = kShadowFormat;
  d.depthOnly = true;
  d.depthBiasConstant = kBiasConstant;
  d.depthBiasSlope = kBiasSlope;
  d.cull = VK_CULL_MODE_NONE;  // the light's projection may mirror the grids' winding
  return d;
}

// Compares a fragment's depth with the map's, filtered over 2 x 2 texels where the format allows.
vk::UniqueSampler createComparisonSampler(vk::Device& device) {
  VkFormatProperties props;
  vkGetPhysicalDeviceFormatProperties(device.physical(), kShadowFormat, &props);
  const bool linear = (props.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = info.minFilter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.compareEnable = VK_TRUE;
  info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;  // lit: no nearer depth towards the sun
  info.maxAnisotropy = 1.0f;
  VkSampler sampler;
  GLOBE_VK_CHECK(vkCreateSampler(device.device(), &info, nullptr, &sampler));
  return vk::UniqueSampler(device.device(), sampler);
}

// Clip units per metre along each of a cascade's clip axes (the lengths of its matrix's rows).
glm::dvec3 clipPerMetre(const glm::dmat4& m) {
  return {glm::length(glm::dvec3(m[0][0], m[1][0], m[2][0])), glm::length(glm::dvec3(m[0][1], m[1][1], m[2][1])),
          glm::length(glm::dvec3(m[0][2], m[1][2], m[2][2]))};
}

// Whether a sphere of `radius_m` at `relative` (metres from the camera) may lie in the box of cascade
// `c` (x, y across the light; z: not beyond the far side, any distance towards the sun, where it may
// shade the box's ground). `perMetre`: clipPerMetre of its matrix.
bool mayCast(const ShadowCascade& c, const glm::dvec3& perMetre, const glm::dvec3& relative, double radius_m) {
  const glm::dvec4 p = c.clipFromCamera * glm::dvec4(relative, 1.0);
  const glm::dvec3 r = radius_m * perMetre;
  return std::abs(p.x) <= 1.0 + r.x && std::abs(p.y) <= 1.0 + r.y && p.z <= 1.0 + r.z;
}

}  // namespace

TerrainShadows::TerrainShadows(vk::Device& device, uint32_t gridCells, const TerrainStyle& style, GridRanges grids,
                               uint32_t resolution)
    : device_(device),
      cells_(gridCells),
      style_(style),
      grids_(grids),
      resolution_(resolution),
      pipeline_(device, shadowDesc()) {
  image_ = vk::createImage(device, kShadowFormat, {resolution, resolution}, kShadowCascades, 1, VK_SAMPLE_COUNT_1_BIT,
                           VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "shadow maps");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device.device(), image_, &req);
  memory_ = vk::allocateMemory(device, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  GLOBE_VK_CHECK(vkBindImageMemory(device.device(), image_, memory_, 0));
  arrayView_ =
      vk::createArrayView(device.device(), image_, kShadowFormat, kShadowCascades, 0, 1, VK_IMAGE_ASPECT_DEPTH_BIT);
  for (uint32_t c = 0; c < kShadowCascades; ++c)
    layerViews_[c] = vk::createArrayView(device.device(), image_, kShadowFormat, 1, 0, 1, VK_IMAGE_ASPECT_DEPTH_BIT, c);
  sampler_ = createComparisonSampler(device);
  // Readable from the start: a frame drawn before any shadow pass samples it (with no cascade in use).
  device.submitAndWait([&](VkCommandBuffer cmd) {
    vk::transitionImage(cmd, image_, {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, kShadowCascades}, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  });
}

TerrainShadows::~TerrainShadows() = default;

vk::ImageDescriptor TerrainShadows::sampled() const {
  return {{GLOBE_TERRAIN_SHADOW_BINDING}, {sampler_, arrayView_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
}

void TerrainShadows::ensureCapacity(uint32_t frameIndex, size_t instances) {
  if (instances <= capacity_[frameIndex] && frames_[frameIndex].handle() != VK_NULL_HANDLE) return;
  const size_t capacity = std::max({instances, capacity_[frameIndex] + capacity_[frameIndex] / 2, size_t(256)});
  frames_[frameIndex] = vk::Buffer(device_, kHeaderBytes + VkDeviceSize(capacity) * sizeof(gpu::TerrainInstance),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                   vk::MemoryUse::HostVisible, "shadow frame");
  capacity_[frameIndex] = capacity;
}

void TerrainShadows::writeInstances(const ShadowCascades& cascades, const gpu::TerrainFrame& frame,
                                    std::span<const DrawNode> nodes, const glm::dvec3& origin_m,
                                    const glm::dvec3& camera_m, const PayloadPages& payloads, uint32_t frameIndex) {
  members_.clear();
  casters_.fill(0);
  std::array<glm::dvec3, kShadowCascades> perMetre{};
  for (uint32_t c = 0; c < cascades.count; ++c) perMetre[c] = clipPerMetre(cascades.cascades[c].clipFromCamera);
  nodeInstances_.resize(nodes.size());
  for (uint32_t k = 0; k < nodes.size(); ++k) {
    // A sphere of 1.5 node widths holds the node with its relief.
    const double sphere_m = 1.5 * nominalNodeWidth(nodes[k].id.level, style_.radius_m);
    const size_t before = members_.size();
    for (uint32_t c = 0; c < cascades.count; ++c) {
      if (!mayCast(cascades.cascades[c], perMetre[c], nodes[k].centre_m - camera_m, sphere_m)) continue;
      const uint32_t grid = nodes[k].partial ? 1u : 0u;
      members_.push_back({(c * kGrids + grid) * pageCount_ + payloads.page(nodes[k].slot), k});
      ++casters_[c];
    }
    // Once per node, whichever cascades draw it.
    if (members_.size() > before) nodeInstances_[k] = terrainInstance(nodes[k], origin_m, payloads, cells_);
  }
  std::stable_sort(members_.begin(), members_.end(), [](auto a, auto b) { return a.first < b.first; });
  ensureCapacity(frameIndex, members_.size());
  auto* bytes = static_cast<unsigned char*>(frames_[frameIndex].mapped());
  for (uint32_t c = 0; c < cascades.count; ++c) {
    gpu::TerrainFrame cascadeFrame = frame;
    const glm::mat4 clip(cascades.cascades[c].clipFromCamera);
    std::memcpy(cascadeFrame.clipFromCamera.m, glm::value_ptr(clip), sizeof(cascadeFrame.clipFromCamera.m));
    cascadeFrame.options.z = 0;  // grids only
    std::memcpy(bytes + c * kCascadeFrameBytes, &cascadeFrame, sizeof(cascadeFrame));
  }
  auto* instances = reinterpret_cast<gpu::TerrainInstance*>(bytes + kHeaderBytes);
  instancesOf_.assign(size_t(kShadowCascades) * kGrids * pageCount_, 0);
  for (size_t i = 0; i < members_.size(); ++i) {
    instances[i] = nodeInstances_[members_[i].second];
    ++instancesOf_[members_[i].first];
  }
  firstInstance_.assign(instancesOf_.size(), 0);
  for (size_t g = 1; g < instancesOf_.size(); ++g) firstInstance_[g] = firstInstance_[g - 1] + instancesOf_[g - 1];
}

void TerrainShadows::prepare(VkCommandBuffer cmd, const PassFrame& frame, PassMarks& marks) {
  marks.write(cmd, kMarkShadowsBegin);
  cascades_ = {};
  if (!frame.nodes.empty() && frame.constants != nullptr) {
    cascades_ = fitShadowCascades(
        {&frame.camera, glm::normalize(style_.sunDirection), frame.groundRadius_m, style_.terrainRadii_m, resolution_});
    record(cmd, frame);
  }
  marks.write(cmd, kMarkShadowsEnd);
}

void TerrainShadows::record(VkCommandBuffer cmd, const PassFrame& frame) {
  const PayloadPages& payloads = frame.payloads;
  pageCount_ = std::max(payloads.pageCount(), 1u);
  writeInstances(cascades_, *frame.constants, frame.nodes, frame.origin_m, frame.camera.position_m, payloads,
                 frame.frameIndex);
  const VkImageSubresourceRange all{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, kShadowCascades};
  // The previous frame's maps are not needed: every cascade in use is cleared.
  vk::transitionImage(cmd, image_, all, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
  for (uint32_t c = 0; c < cascades_.count; ++c) recordCascade(cmd, c, payloads, frame.frameIndex);
  vk::transitionImage(cmd, image_, all, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void TerrainShadows::recordCascade(VkCommandBuffer cmd, uint32_t cascade, const PayloadPages& payloads,
                                   uint32_t frameIndex) const {
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = layerViews_[cascade];
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth.clearValue.depthStencil = {1.0f, 0};  // the far side: nothing between there and the sun
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, {resolution_, resolution_}};
  info.layerCount = 1;
  info.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &info);
  setWholeViewport(cmd, {resolution_, resolution_});
  vkCmdBindIndexBuffer(cmd, grids_.indices, 0, VK_INDEX_TYPE_UINT32);
  const vk::Buffer& buffer = frames_[frameIndex];
  const VkDescriptorBufferInfo instances{buffer.handle(), kHeaderBytes, buffer.size() - kHeaderBytes};
  const VkDescriptorBufferInfo constants{buffer.handle(), cascade * kCascadeFrameBytes, sizeof(gpu::TerrainFrame)};
  for (uint32_t grid = 0; grid < kGrids; ++grid) {
    for (uint32_t page = 0; page < pageCount_; ++page) {
      const size_t g = (size_t(cascade) * kGrids + grid) * pageCount_ + page;
      if (instancesOf_[g] == 0) continue;
      const gpu::TerrainDrawPush push{grid == 0 ? cells_ : cells_ / 2, 0};
      pipeline_.bind(cmd, {instances, payloads.window(page), constants}, &push, sizeof(push));
      vkCmdDrawIndexed(cmd, grids_.count[grid], instancesOf_[g], grids_.first[grid], 0, firstInstance_[g]);
    }
  }
  vkCmdEndRendering(cmd);
}

}  // namespace globe
