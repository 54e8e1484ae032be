#include "engine/terrain_renderer.h"

#include <meshoptimizer.h>

#include "engine/render_output.h"
#include "engine/vk_check.h"
#include "planet/face_mapping.h"
#include "shaders/include/payload_layout.h"
#include "shaders/include/terrain_layout.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace globe {
namespace {

struct SkyPush {
  ViewRays rays;
  float zenith[4];
  float horizon[4];
  float local[4];
};
static_assert(sizeof(SkyPush) == 96);

// Per-frame buffer: the TerrainFrame constants, then the instances at an offset every device accepts
// for a storage-buffer binding (minStorageBufferOffsetAlignment is at most 256).
constexpr VkDeviceSize kFrameHeaderBytes = 512;
static_assert(sizeof(gpu::TerrainFrame) <= kFrameHeaderBytes);

vk::GraphicsPipelineDesc terrainDesc(VkFormat colourFormat, bool wireframe, VertexPositions positions) {
  vk::GraphicsPipelineDesc d;
  const bool reprojected = positions == VertexPositions::kReprojected;
  d.vertexShader = reprojected ? "terrain_reprojected.vert" : "terrain.vert";
  d.fragmentShader = "terrain.frag";
  // 0: instances, 1: payloads, 2: frame constants (uniform); reprojected: 3 nodes' (u, v), 4 faces.
  d.storageBuffers = reprojected ? 5 : 3;
  d.uniformMask = 1u << 2;
  d.pushConstantBytes = sizeof(gpu::TerrainDrawPush);
  d.colourFormat = colourFormat;
  d.wireframe = wireframe;
  return d;
}

// Triangles of an n x n grid (vertex i + j (n+1)), every cell split along (i, j)-(i+1, j+1), then the
// skirt quads of its four edges (skirt vertex (n+1)^2 + e (n+1) + t below grid vertex t of edge e).
// Returns the grid's own index count.
uint32_t appendGrid(uint32_t n, std::vector<uint32_t>& out) {
  const uint32_t side = n + 1;
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t v00 = j * side + i, v10 = v00 + 1, v01 = v00 + side, v11 = v01 + 1;
      out.insert(out.end(), {v00, v10, v11, v00, v11, v01});
    }
  }
  const uint32_t gridIndices = 6 * n * n;
  const auto edgeVertex = [&](uint32_t edge, uint32_t t) -> uint32_t {
    switch (edge) {
      case 0: return t;                 // j = 0
      case 1: return t * side + n;      // i = n
      case 2: return n * side + t;      // j = n
      default: return t * side;         // i = 0
    }
  };
  for (uint32_t e = 0; e < 4; ++e) {
    for (uint32_t t = 0; t < n; ++t) {
      const uint32_t g0 = edgeVertex(e, t), g1 = edgeVertex(e, t + 1);
      const uint32_t s0 = side * side + e * side + t, s1 = s0 + 1;
      out.insert(out.end(), {g0, g1, s1, g0, s1, s0});
    }
  }
  // Row-major order re-shades most vertices (a row is longer than a post-transform cache); meshopt
  // reorders the triangles for cache reuse. Grid and skirts stay separate ranges.
  const size_t first = out.size() - gridIndices - 24 * size_t(n);
  const size_t vertices = size_t(side) * side + 4 * size_t(side);
  meshopt_optimizeVertexCache(&out[first], &out[first], gridIndices, vertices);
  meshopt_optimizeVertexCache(&out[first + gridIndices], &out[first + gridIndices], 24 * size_t(n), vertices);
  return gridIndices;
}

float morphDistance(double metres) {
  // +infinity (depth 0 never morphs) and anything beyond float become FLT_MAX; the shader treats
  // an empty band at FLT_MAX as "never".
  if (!(metres < double(std::numeric_limits<float>::max()))) return std::numeric_limits<float>::max();
  return float(metres);
}

gpu::TerrainVec4 toGpu(const glm::vec3& v, float w) { return {v.x, v.y, v.z, w}; }

}  // namespace

TerrainRenderer::TerrainRenderer(vk::Device& device, uint32_t gridCells, const TerrainStyle& style,
                                 uint32_t initialNodes, VkFormat colourFormat, VertexPositions positions)
    : device_(device),
      cells_(gridCells),
      style_(style),
      solid_(device, terrainDesc(colourFormat, false, positions)),
      sky_(device, [&] {
        vk::GraphicsPipelineDesc d;
        d.vertexShader = "fullscreen.vert";
        d.fragmentShader = "terrain_sky.frag";
        d.pushConstantBytes = sizeof(SkyPush);
        d.colourFormat = colourFormat;
        d.depthTest = true;  // GREATER_OR_EQUAL against depth 0: passes only where nothing was drawn
        d.depthWrite = false;
        return d;
      }()) {
  assert(gridCells >= 16 && gridCells <= 256 && (gridCells & (gridCells - 1)) == 0);
  VkPhysicalDeviceFeatures features{};
  vkGetPhysicalDeviceFeatures(device.physical(), &features);
  if (features.fillModeNonSolid) {
    wireframe_ = std::make_unique<vk::GraphicsPipeline>(device, terrainDesc(colourFormat, true, positions));
  }

  std::vector<uint32_t> indices;
  indices.reserve(size_t(6) * (gridCells * gridCells + gridCells * gridCells / 4 + 6 * gridCells));
  fullGridIndices_ = appendGrid(gridCells, indices);
  fullIndices_ = uint32_t(indices.size());
  halfGridIndices_ = appendGrid(gridCells / 2, indices);
  halfIndices_ = uint32_t(indices.size()) - fullIndices_;

  const VkDeviceSize bytes = indices.size() * sizeof(uint32_t);
  indices_ = vk::Buffer(device, bytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        vk::MemoryUse::DeviceLocal, "terrain grid indices");
  vk::Buffer staging(device, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::HostVisible,
                     "terrain grid indices (staging)");
  std::memcpy(staging.mapped(), indices.data(), size_t(bytes));
  device.submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{0, 0, bytes};
    vkCmdCopyBuffer(cmd, staging.handle(), indices_.handle(), 1, &copy);
  });
  positions_ = positions;
  if (positions_ == VertexPositions::kReprojected) {
    faces_ = vk::Buffer(device, 30 * sizeof(FaceCornersGpu), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        vk::MemoryUse::HostVisible, "terrain face corners");
    auto* faces = static_cast<FaceCornersGpu*>(faces_.mapped());
    for (int f = 0; f < 30; ++f) faces[f] = RhombusFaceMapping::get().gpuCorners(f);
  }
  for (uint32_t f = 0; f < kFramesInFlight; ++f) ensureCapacity(f, std::max(initialNodes, 1u));
}

TerrainRenderer::~TerrainRenderer() = default;

VkDescriptorBufferInfo TerrainRenderer::instanceDescriptor(uint32_t frameIndex) const {
  const vk::Buffer& b = frames_[frameIndex];
  return {b.handle(), kFrameHeaderBytes, b.size() - kFrameHeaderBytes};
}

VkDescriptorBufferInfo TerrainRenderer::constantsDescriptor(uint32_t frameIndex) const {
  return {frames_[frameIndex].handle(), 0, sizeof(gpu::TerrainFrame)};
}

const unsigned char* TerrainRenderer::instanceBytes(uint32_t frameIndex) const {
  return static_cast<const unsigned char*>(frames_[frameIndex].mapped()) + kFrameHeaderBytes;
}

void TerrainRenderer::ensureCapacity(uint32_t frameIndex, uint32_t nodes) {
  if (nodes <= capacity_[frameIndex]) return;
  // Grow geometrically so a slowly rising node count does not reallocate every frame. The caller
  // waited for this frame index, so the old buffer is idle and can go now.
  const uint32_t capacity = std::max(nodes, capacity_[frameIndex] + capacity_[frameIndex] / 2);
  frames_[frameIndex] = vk::Buffer(device_, kFrameHeaderBytes + VkDeviceSize(capacity) * sizeof(gpu::TerrainInstance),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::HostVisible,
                                   frameIndex == 0 ? "terrain frame 0" : "terrain frame 1");
  if (positions_ == VertexPositions::kReprojected) {
    reprojection_[frameIndex] =
        vk::Buffer(device_, sizeof(gpu::TerrainReprojectionFrame) + VkDeviceSize(capacity) * sizeof(gpu::TerrainReprojectionNode),
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible, "terrain reprojection");
  }
  capacity_[frameIndex] = capacity;
}

void TerrainRenderer::fillReprojection(uint32_t frameIndex, const Camera& camera, std::span<const DrawNode> nodes,
                                       uint32_t full) {
  auto* bytes = static_cast<unsigned char*>(reprojection_[frameIndex].mapped());
  gpu::TerrainReprojectionFrame header{{camera.position_m.x, camera.position_m.y, camera.position_m.z, style_.radius_m}};
  std::memcpy(bytes, &header, sizeof(header));
  auto* out = reinterpret_cast<gpu::TerrainReprojectionNode*>(bytes + sizeof(header));
  uint32_t nextFull = 0, nextPartial = full;
  for (const DrawNode& n : nodes) {
    out[n.partial ? nextPartial++ : nextFull++].uv = {n.id.uMin(), n.id.vMin(), n.id.size(), double(n.id.face)};
  }
}

void TerrainRenderer::recordSky(VkCommandBuffer cmd, const Camera& camera) const {
  const double distance_m = glm::length(camera.position_m);
  const glm::dvec3 local = distance_m > 0.0 ? camera.position_m / distance_m : glm::dvec3(0, 0, 1);
  const double altitude_m = distance_m - style_.radius_m;
  const float atmosphere = float(std::clamp(1.0 - altitude_m / style_.atmosphereHeight_m, 0.0, 1.0));
  const glm::vec3 z = style_.zenithColour, h = style_.horizonColour;
  SkyPush push{viewRays(camera, 0.0f),
               {z.x, z.y, z.z, atmosphere},
               {h.x, h.y, h.z, 0.0f},
               {float(local.x), float(local.y), float(local.z), 0.0f}};
  sky_.bind(cmd, {}, &push, sizeof(push));
  vkCmdDraw(cmd, 3, 1, 0, 0);
}

DrawStats TerrainRenderer::record(VkCommandBuffer cmd, const Camera& camera, const glm::dvec3& origin_m,
                                  std::span<const DrawNode> nodes, const vk::Buffer& payloads,
                                  uint32_t frameIndex) {
  assert(frameIndex < kFramesInFlight);
  DrawStats stats;
  // The sky goes last, behind everything: its fullscreen triangle lies at the far plane (depth 0),
  // so the depth test keeps only the pixels no terrain covered, and those are the only ones shaded.
  struct SkyLast {
    const TerrainRenderer& renderer;
    VkCommandBuffer cmd;
    const Camera& camera;
    DrawStats& stats;
    ~SkyLast() {
      if (!renderer.style_.sky) return;
      renderer.recordSky(cmd, camera);
      ++stats.drawCalls;
    }
  } skyLast{*this, cmd, camera, stats};
  if (nodes.empty()) return stats;
  ensureCapacity(frameIndex, uint32_t(nodes.size()));
  vk::Buffer& buffer = frames_[frameIndex];
  auto* bytes = static_cast<unsigned char*>(buffer.mapped());

  // Frame constants. The view matrix has no translation: vertices arrive camera-relative.
  gpu::TerrainFrame frame{};
  const glm::mat4 clipFromCamera(camera.projection() * camera.viewFromWorld(camera.position_m));
  std::memcpy(frame.clipFromCamera.m, glm::value_ptr(clipFromCamera), sizeof(frame.clipFromCamera.m));
  const glm::dvec3 cameraRelative = camera.position_m - origin_m;
  const glm::vec3 high(cameraRelative);
  const glm::vec3 low(cameraRelative - glm::dvec3(high));
  frame.cameraHigh = toGpu(high, 0.0f);
  frame.cameraLow = toGpu(low, 0.0f);
  frame.planetCentre = toGpu(glm::vec3(-origin_m), float(style_.radius_m));
  frame.sun = toGpu(glm::vec3(glm::normalize(style_.sunDirection)), style_.ambient);
  TerrainDebugView view = style_.debug;
  if (view == TerrainDebugView::kWireframe && !wireframe_) view = TerrainDebugView::kLodColours;
  const bool skirts = style_.skirtOutward > 0.0f || style_.skirtDrop > 0.0f;
  frame.options = {cells_,
                   view == TerrainDebugView::kShaded ? GLOBE_TERRAIN_SHADED
                   : view == TerrainDebugView::kLodColours ? GLOBE_TERRAIN_LOD_COLOURS
                                                           : GLOBE_TERRAIN_WIREFRAME,
                   skirts ? 1u : 0u, 0u};
  frame.skirt = {style_.skirtOutward, style_.skirtDrop, 0.0f, 0.0f};
  frame.ramp = packColourRamp(style_.ramp);
  std::memcpy(bytes, &frame, sizeof(frame));

  // Instances: full nodes first, then partial ones, so each draw is one contiguous instance range.
  auto* instances = reinterpret_cast<gpu::TerrainInstance*>(bytes + kFrameHeaderBytes);
  const uint32_t slotVec4 = GLOBE_PAYLOAD_VEC4_PER_SLOT(cells_);
  uint32_t full = 0;
  for (const DrawNode& n : nodes) full += n.partial ? 0u : 1u;
  uint32_t nextFull = 0, nextPartial = full;
  for (const DrawNode& n : nodes) {
    gpu::TerrainInstance inst{};
    // Double first, float last: the offset is a multiple of the level's quantum and small.
    inst.offset = toGpu(glm::vec3(n.centre_m - origin_m), 0.0f);
    inst.morph = {morphDistance(n.morph.start_m), morphDistance(n.morph.end_m), 0.0f, 0.0f};
    inst.info = {n.slot * slotVec4, n.partial ? 2u : 1u, uint32_t(n.id.level) - (n.partial ? 1u : 0u), 0u};
    instances[n.partial ? nextPartial++ : nextFull++] = inst;
  }
  const uint32_t partial = uint32_t(nodes.size()) - full;

  const vk::GraphicsPipeline& pipeline =
      view == TerrainDebugView::kWireframe ? *wireframe_ : solid_;
  gpu::TerrainDrawPush push{cells_, 0};
  if (positions_ == VertexPositions::kReprojected) {
    fillReprojection(frameIndex, camera, nodes, full);
    pipeline.bind(cmd,
                  {instanceDescriptor(frameIndex), payloads.descriptor(), constantsDescriptor(frameIndex),
                   reprojection_[frameIndex].descriptor(), faces_.descriptor()},
                  &push, sizeof(push));
  } else {
    pipeline.bind(cmd, {instanceDescriptor(frameIndex), payloads.descriptor(), constantsDescriptor(frameIndex)}, &push,
                  sizeof(push));
  }
  vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
  const uint32_t fullCount = skirts ? fullIndices_ : fullGridIndices_;
  const uint32_t halfCount = skirts ? halfIndices_ : halfGridIndices_;
  if (full > 0) {
    vkCmdDrawIndexed(cmd, fullCount, full, 0, 0, 0);
    ++stats.drawCalls;
    stats.triangles += uint64_t(fullCount / 3) * full;
  }
  if (partial > 0) {
    push.drawnCells = cells_ / 2;
    vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(push), &push);
    vkCmdDrawIndexed(cmd, halfCount, partial, fullIndices_, 0, full);
    ++stats.drawCalls;
    stats.triangles += uint64_t(halfCount / 3) * partial;
  }
  stats.nodes = uint32_t(nodes.size());
  stats.partialNodes = partial;
  return stats;
}

}  // namespace globe
