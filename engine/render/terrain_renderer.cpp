#include "engine/render/terrain_renderer.h"

#include "engine/render/atmosphere_passes.h"
#include "engine/render/grid_indices.h"
#include "engine/render/terrain_haze.h"
#include "engine/render/terrain_instance.h"
#include "engine/render/terrain_pipelines.h"
#include "engine/render/terrain_shadows.h"
#include "engine/vk/vk_check.h"
#include "planet/geometry/face_mapping.h"
#include "shaders/include/payload_layout.h"
#include "shaders/include/terrain_layout.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace globe {
namespace {

// Per-frame buffer: the TerrainFrame constants, then the instances at an offset every device accepts
// for a storage-buffer binding (minStorageBufferOffsetAlignment is at most 256).
constexpr VkDeviceSize kFrameHeaderBytes = 768;
static_assert(sizeof(gpu::TerrainFrame) <= kFrameHeaderBytes);

// Draw groups: the index buffer's four ranges (full grid, half grid, full skirt strip, half skirt
// strip) for nodes without sea, then the same four for nodes with sea, drawn with the water shader
// (their skirts too: a skirt shows through sub-pixel gaps, and below the sea it must be sea); then
// the same eight for the nodes near the camera drawn with the land cover's splat
// (TerrainStyle::detailRange_m; their skirts are drawn with the others'); then all sixteen again for
// the nodes whose fragments read the colour layer (DrawNode::colourLayer).
constexpr uint32_t kIndexRanges = 4;
constexpr uint32_t kWaterGroups = kIndexRanges;        // groups 4..7: nodes with sea
constexpr uint32_t kDetailGroups = 2 * kIndexRanges;   // groups 8..15: the same near the camera
constexpr uint32_t kColourGroups = 2 * kDetailGroups;  // groups 16..31: the same with the colour layer
constexpr uint32_t kDrawGroups = 2 * kColourGroups;
// Grids before skirts, so that the pass marks split them.
constexpr std::array<uint32_t, 24> kGroupOrder{0,  1,  16, 17, 4, 5, 20, 21, 8, 9, 24, 25,
                                               12, 13, 28, 29, 2, 3, 18, 19, 6, 7, 22, 23};

// The group of a node's grid (range 0) or skirts (range 2); `detail`: drawn with the splat.
uint32_t drawGroup(const DrawNode& n, uint32_t range, bool detail) {
  return range + (n.partial ? 1u : 0u) + (n.water ? kWaterGroups : 0u) + (detail && range < 2 ? kDetailGroups : 0u) +
         (n.colourLayer ? kColourGroups : 0u);
}

// Sort key of a drawn node for the skirt test below.
std::pair<uint64_t, bool> drawnKey(const NodeId& id, bool partial) { return {id.key(), partial}; }

}  // namespace

TerrainRenderer::TerrainRenderer(vk::Device& device, uint32_t gridCells, const TerrainStyle& style,
                                 VertexPositions positions, uint32_t initialNodes, VkFormat colourFormat,
                                 VkSampleCountFlagBits samples)
    : device_(device),
      cells_(gridCells),
      style_(style),
      detailTiling_(detailTilingFor(style.radius_m)),
      // The reprojected positions (a measurement only) are drawn without the atmosphere.
      atmosphere_(positions == VertexPositions::kStored && style.aerialPerspective ? style.atmosphere : nullptr) {
  assert(gpu::validGridCells(gridCells));
  assert(gpu::validNormalMapScale(style.normalMapScale));
  const TargetFormat target{colourFormat, samples};
  auto wireframe =
      std::async(std::launch::async, makeWireframe, std::ref(device), positions, target, atmosphere_ != nullptr);
  // A planet with an overlay draws the nodes whose overlay varies within their cells with the colour
  // layer, the others without its fetch: two sets, created side by side.
  std::future<SurfacePipelines> coloured;
  if (surfaceShading(style, false, false).colourLayer)
    coloured = std::async(std::launch::async, makeSurfacePipelines, std::ref(device), std::cref(style_), positions,
                          target, atmosphere_ != nullptr, true);
  plain_ = makeSurfacePipelines(device, style_, positions, target, atmosphere_ != nullptr, false);
  if (coloured.valid()) coloured_ = coloured.get();
  wireframe_ = wireframe.get();
  uploadIndices(gridIndexRanges(gridCells));
  const GridRanges grid{indices_.handle(), first_, count_};
  // The passes, in frame order (frame_pass.h).
  if (atmosphere_)
    passes_.push_back((aerial_ = std::make_unique<AerialPerspectivePass>(device, *atmosphere_, style_)).get());
  if (surfaceShading(style, false, false).shadows)
    passes_.push_back((shadows_ = std::make_unique<TerrainShadows>(device, gridCells, style_, grid)).get());
  passes_.push_back(&grids_);
  // Without an atmosphere the background stays the clear colour: black space.
  if (style.atmosphere)
    passes_.push_back(
        (sky_ = std::make_unique<SkyPass>(device, style_, TargetFormat{colourFormat, samples}, gridCells, grid)).get());
  positions_ = positions;
  if (positions_ == VertexPositions::kReprojected) {
    faces_ = vk::Buffer(device, 30 * sizeof(FaceCornersGpu), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        vk::MemoryUse::HostVisible, "terrain face corners");
    auto* faces = static_cast<FaceCornersGpu*>(faces_.mapped());
    for (int f = 0; f < 30; ++f) faces[f] = RhombusFaceMapping::get().gpuCorners(f);
  }
  for (uint32_t f = 0; f < vk::kFramesInFlight; ++f) ensureCapacity(f, std::max(initialNodes, 1u));
}

std::unique_ptr<vk::GraphicsPipeline> TerrainRenderer::makeWireframe(vk::Device& device, VertexPositions positions,
                                                                     TargetFormat target, bool atmosphere) {
  VkPhysicalDeviceFeatures features{};
  vkGetPhysicalDeviceFeatures(device.physical(), &features);
  if (!features.fillModeNonSolid) return nullptr;
  return std::make_unique<vk::GraphicsPipeline>(
      device, terrainDesc(target, true, VK_CULL_MODE_NONE, positions, {false, atmosphere}));
}

void TerrainRenderer::uploadIndices(const GridIndexRanges& ranges) {
  first_ = ranges.first;
  count_ = ranges.count;
  const VkDeviceSize bytes = ranges.indices.size() * sizeof(uint32_t);
  indices_ = vk::Buffer(device_, bytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        vk::MemoryUse::DeviceLocal, "terrain grid indices");
  vk::Buffer staging(device_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::HostVisible,
                     "terrain grid indices (staging)");
  std::memcpy(staging.mapped(), ranges.indices.data(), size_t(bytes));
  device_.submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{0, 0, bytes};
    vkCmdCopyBuffer(cmd, staging.handle(), indices_.handle(), 1, &copy);
  });
}

TerrainRenderer::~TerrainRenderer() = default;

const AtmosphereView* TerrainRenderer::atmosphereView() const { return aerial_ ? &aerial_->view() : nullptr; }

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
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                   vk::MemoryUse::HostVisible, frameIndex == 0 ? "terrain frame 0" : "terrain frame 1");
  if (positions_ == VertexPositions::kReprojected) {
    reprojection_[frameIndex] = vk::Buffer(
        device_, sizeof(gpu::TerrainReprojectionFrame) + VkDeviceSize(capacity) * sizeof(gpu::TerrainReprojectionNode),
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible, "terrain reprojection");
  }
  capacity_[frameIndex] = capacity;
}

gpu::TerrainReprojectionNode* TerrainRenderer::beginReprojection(uint32_t frameIndex, const Camera& camera) {
  auto* bytes = static_cast<unsigned char*>(reprojection_[frameIndex].mapped());
  const gpu::TerrainReprojectionFrame header{
      {camera.position_m.x, camera.position_m.y, camera.position_m.z, style_.radius_m}};
  std::memcpy(bytes, &header, sizeof(header));
  return reinterpret_cast<gpu::TerrainReprojectionNode*>(bytes + sizeof(header));
}

void TerrainRenderer::prepare(VkCommandBuffer cmd, const Camera& camera, const glm::dvec3& origin_m,
                              std::span<const DrawNode> nodes, const PayloadPages& payloads, uint32_t frameIndex,
                              double groundRadius_m) {
  if (shadows_) shadows_->endFrame();  // the constants below carry no cascades
  // The camera's constants, for the shadow casters alone: written only when they are drawn.
  gpu::TerrainFrame constants;
  const bool castsShadows = shadows_ && !nodes.empty();
  if (castsShadows) writeFrameConstants(reinterpret_cast<unsigned char*>(&constants), camera, origin_m, false);
  const PassFrame frame{camera,     origin_m,       nodes,   payloads,
                        frameIndex, groundRadius_m, nullptr, castsShadows ? &constants : nullptr};
  PassMarks marks(timestamps_, kMarkShadowsBegin);
  for (FramePass* pass : passes_) pass->prepare(cmd, frame, marks);
  marks.write(cmd, kMarkShadowsEnd);
}

DrawStats TerrainRenderer::record(VkCommandBuffer cmd, const Camera& camera, const glm::dvec3& origin_m,
                                  std::span<const DrawNode> nodes, const PayloadPages& payloads, uint32_t frameIndex,
                                  const ImageryBinding* imagery) {
  assert(frameIndex < vk::kFramesInFlight);
  assert((imagery != nullptr) == style_.imagery);
  const PassFrame frame{camera, origin_m, nodes, payloads, frameIndex, 0.0, imagery, nullptr};
  DrawStats stats;
  PassMarks marks(timestamps_, kMarkGridsBegin);
  for (FramePass* pass : passes_) pass->record(cmd, frame, marks, stats);
  marks.write(cmd, kMarkSkyEnd);
  if (shadows_) shadows_->endFrame();  // drawn with this frame: the next record() without prepare() has none
  return stats;
}

void TerrainRenderer::GridsPass::record(VkCommandBuffer cmd, const PassFrame& frame, PassMarks& marks,
                                        DrawStats& stats) {
  marks.write(cmd, kMarkGridsBegin);
  if (!frame.nodes.empty())
    stats += renderer_.recordTerrain(cmd, frame.camera, frame.origin_m, frame.nodes, frame.payloads, frame.frameIndex,
                                     frame.imagery, marks);
}

DrawStats TerrainRenderer::recordTerrain(VkCommandBuffer cmd, const Camera& camera, const glm::dvec3& origin_m,
                                         std::span<const DrawNode> nodes, const PayloadPages& payloads,
                                         uint32_t frameIndex, const ImageryBinding* imagery, PassMarks& marks) {
  const bool skirts = style_.skirtOutward > 0.0f || style_.skirtDrop > 0.0f;
  const std::array<uint32_t, 2> skirtEdges = skirts ? markSkirtedEdges(nodes) : std::array<uint32_t, 2>{0, 0};
  ensureCapacity(frameIndex, uint32_t(nodes.size()) + skirtEdges[0] + skirtEdges[1]);
  auto* bytes = static_cast<unsigned char*>(frames_[frameIndex].mapped());
  const TerrainDebugView view = writeFrameConstants(bytes, camera, origin_m, skirts);
  // kReprojected: each instance's node (u, v) corner, size and face, at the same index.
  gpu::TerrainReprojectionNode* reprojection =
      positions_ == VertexPositions::kReprojected ? beginReprojection(frameIndex, camera) : nullptr;
  const uint32_t pageCount = std::max(payloads.pageCount(), 1u);
  orderNearFirst(nodes, camera.position_m, view);
  groupInstances(nodes, payloads, pageCount, skirts);
  const uint32_t partial = writeInstances(bytes, origin_m, nodes, payloads, pageCount, skirts, reprojection);
  DrawStats stats = recordDraws(cmd, payloads, pageCount, frameIndex, view, reprojection != nullptr, imagery, marks);
  stats.nodes = uint32_t(nodes.size());
  stats.partialNodes = partial;
  stats.skirtEdges = skirtEdges[0] + skirtEdges[1];
  return stats;
}

std::array<uint32_t, 2> TerrainRenderer::markSkirtedEdges(std::span<const DrawNode> nodes) {
  // Skirted edges of full nodes, then of partial ones (one skirt instance each).
  std::array<uint32_t, 2> skirtEdges{0, 0};
  drawn_.clear();
  for (const DrawNode& n : nodes) drawn_.push_back(drawnKey(n.id, n.partial));
  std::sort(drawn_.begin(), drawn_.end());
  skirtMask_.resize(nodes.size());
  for (size_t k = 0; k < nodes.size(); ++k) {
    // An edge needs no skirt when its same-level neighbour is drawn the same way (same level,
    // both full or both partial): they share bit-identical vertices and the same morph band, so
    // the rasteriser's fill rule leaves no gap. Gaps open only where the level or the payload
    // quantum changes (docs/rendering.md, "Skirts").
    uint8_t mask = 0;
    for (int e = 0; e < 4; ++e) {
      if (!std::binary_search(drawn_.begin(), drawn_.end(), drawnKey(edgeNeighbour(nodes[k].id, e), nodes[k].partial)))
        mask |= uint8_t(1u << e);
    }
    skirtMask_[k] = mask;
    skirtEdges[nodes[k].partial ? 1 : 0] += uint32_t(std::popcount(mask));
  }
  return skirtEdges;
}

TerrainDebugView TerrainRenderer::writeFrameConstants(unsigned char* bytes, const Camera& camera,
                                                      const glm::dvec3& origin_m, bool skirts) const {
  // The view matrix has no translation: vertices arrive camera-relative.
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
  if (view == TerrainDebugView::kLandCover && !style_.landCover()) view = TerrainDebugView::kShaded;
  frame.options = {cells_,
                   view == TerrainDebugView::kShaded       ? GLOBE_TERRAIN_SHADED
                   : view == TerrainDebugView::kLodColours ? GLOBE_TERRAIN_LOD_COLOURS
                   : view == TerrainDebugView::kLandCover  ? GLOBE_TERRAIN_LAND_COVER
                                                           : GLOBE_TERRAIN_WIREFRAME,
                   skirts ? 1u : 0u, cells_ * style_.normalMapScale};
  frame.skirt = {style_.skirtOutward, style_.skirtDrop, 0.0f, 0.0f};
  const Water& w = style_.water;
  // Without water the sea level is -FLT_MAX: nothing is below it (terrain_vertex.glsl).
  const float seaLevel_m = w.enabled ? float(style_.seaLevel_m) : -std::numeric_limits<float>::max();
  frame.waterShallow = toGpu(w.shallow_colour, seaLevel_m);
  frame.waterDeep = toGpu(w.deep_colour, float(1.0 / w.depth_scale_m));
  frame.skyZenith = toGpu(style_.zenithColour, 0.0f);
  frame.skyHorizon = toGpu(style_.horizonColour, 0.0f);
  frame.centreFromCamera = toGpu(glm::vec3(-camera.position_m), 0.0f);  // once per frame, in double
  // The splat's fade near the camera (coverNear): 0 to 1 over view depths [range / 3, range], as
  // a / depth + b of the fragment's reversed-Z depth (= near / view depth); 0, 0: never faded.
  glm::vec2 fade(0.0f);
  if (style_.coverNear()) {
    const double start_m = style_.detailRange_m / 3.0, width_m = style_.detailRange_m - start_m;
    fade = glm::vec2(float(camera.near_m / width_m), float(-start_m / width_m));
  }
  frame.detailLevels = {float(detailTiling_.fineLevel), float(detailTiling_.coarseLevel), fade.x, fade.y};
  writeShadowConstants(frame);
  // The pipelines with the atmosphere's light read its tables instead (terrain_atmosphere.glsl).
  const AtmosphereLuts* air = style_.atmosphere;
  writeHazeConstants(frame, air ? &air->packed() : nullptr, air ? air->irradianceData() : nullptr,
                     atmosphereCamera(style_.shape, style_.radius_m, camera.position_m), style_.sunDirection);
  std::memcpy(bytes, &frame, sizeof(frame));
  return view;
}

void TerrainRenderer::writeShadowConstants(gpu::TerrainFrame& frame) const {
  const ShadowCascades none{};
  const ShadowCascades& cascades = shadows_ ? shadows_->cascades() : none;
  frame.shadow = {float(cascades.count), kShadowFadeStart, 0.0f, 0.0f};
  float bias[kShadowCascades]{};
  for (uint32_t c = 0; c < cascades.count; ++c) {
    const ShadowCascade& cascade = cascades.cascades[c];
    const glm::mat4 clip(cascade.clipFromCamera);
    std::memcpy(frame.shadowFromCamera[c].m, glm::value_ptr(clip), sizeof(frame.shadowFromCamera[c].m));
    // Two texels along the sunlight, times 1 + the slope's tangent in the fragment stage
    // (terrain_shadows.glsl): 1.5 left texel-sized blocks of self-shadow on bumps at the 2 m camera.
    bias[c] = float(kShadowBiasTexels * cascade.texel_m / cascade.depth_m);
  }
  static_assert(kShadowCascades == 3);
  frame.shadowBias = {bias[0], bias[1], bias[2], 0.0f};
}

void TerrainRenderer::groupInstances(std::span<const DrawNode> nodes, const PayloadPages& payloads, uint32_t pageCount,
                                     bool skirts) {
  // Instances grouped by draw: index range (full grid, half grid, full skirts, half skirts), then
  // payload page (one page unless the pool outgrows one storage-buffer binding), so each draw is one
  // contiguous instance range with its page's window bound.
  instancesOf_.assign(size_t(kDrawGroups) * pageCount, 0);
  for (size_t k = 0; k < nodes.size(); ++k) {
    const uint32_t page = payloads.page(nodes[k].slot);
    ++instancesOf_[size_t(drawGroup(nodes[k], 0, detailNode_[k])) * pageCount + page];
    if (skirts)
      instancesOf_[size_t(drawGroup(nodes[k], 2, false)) * pageCount + page] += uint32_t(std::popcount(skirtMask_[k]));
  }
  firstInstance_.assign(instancesOf_.size(), 0);
  for (size_t g = 1; g < instancesOf_.size(); ++g) firstInstance_[g] = firstInstance_[g - 1] + instancesOf_[g - 1];
}

void TerrainRenderer::orderNearFirst(std::span<const DrawNode> nodes, const glm::dvec3& camera_m,
                                     TerrainDebugView view) {
  // Near nodes first within each draw: the depth test then rejects most hidden fragments before
  // they are shaded (lavapipe skips a block's shader when its whole depth mask fails).
  distances_.resize(nodes.size());
  order_.resize(nodes.size());
  detailNode_.assign(nodes.size(), 0);
  for (size_t k = 0; k < nodes.size(); ++k) {
    distances_[k] = glm::length(nodes[k].centre_m - camera_m);
    order_[k] = uint32_t(k);
    // The splat's fade is by view depth, at most the distance: a node is near when its centre is
    // within twice the range (view depth >= half the distance within a field of view of 120
    // degrees) plus a generous radius (1.5 node widths, for the relief), so every fragment of the
    // nodes drawn without it is faded out already. The land cover view needs every node's masks.
    if (style_.coverNear()) {
      const double radius_m = 1.5 * nominalNodeWidth(nodes[k].id.level, style_.radius_m);
      detailNode_[k] = view == TerrainDebugView::kLandCover || distances_[k] - radius_m < 2.0 * style_.detailRange_m;
    }
  }
  std::sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) { return distances_[a] < distances_[b]; });
}

uint32_t TerrainRenderer::writeInstances(unsigned char* bytes, const glm::dvec3& origin_m,
                                         std::span<const DrawNode> nodes, const PayloadPages& payloads,
                                         uint32_t pageCount, bool skirts, gpu::TerrainReprojectionNode* reprojection) {
  auto* instances = reinterpret_cast<gpu::TerrainInstance*>(bytes + kFrameHeaderBytes);
  std::vector<uint32_t>& next = nextInstance_;
  next = firstInstance_;
  uint32_t partial = 0;
  for (const uint32_t k : order_) {
    const DrawNode& n = nodes[k];
    const gpu::TerrainReprojectionNode mapping{{n.id.uMin(), n.id.vMin(), n.id.size(), double(n.id.face)}};
    gpu::TerrainInstance inst = terrainInstance(n, origin_m, payloads, cells_);
    inst.imagery = {n.imageryCell, payloads.localSlot(n.slot) * style_.surfaceLayersPerSlot, 0u, 0u};
    if (style_.landCover()) {  // only the _cover vertex stages read it
      const glm::vec4 detail = detailTileOffsets(n.id, detailTiling_);
      inst.detail = {detail.x, detail.y, detail.z, detail.w};
    }
    partial += n.partial ? 1u : 0u;
    const uint32_t page = payloads.page(n.slot);
    const size_t grid = size_t(drawGroup(n, 0, detailNode_[k])) * pageCount + page;
    const size_t skirt = size_t(drawGroup(n, 2, false)) * pageCount + page;
    if (reprojection) reprojection[next[grid]] = mapping;
    instances[next[grid]++] = inst;
    for (uint32_t e = 0; skirts && e < 4; ++e) {
      if ((skirtMask_[k] >> e & 1u) == 0) continue;
      inst.info.w = e;
      if (reprojection) reprojection[next[skirt]] = mapping;
      instances[next[skirt]++] = inst;
    }
  }
  return partial;
}

DrawStats TerrainRenderer::recordDraws(VkCommandBuffer cmd, const PayloadPages& payloads, uint32_t pageCount,
                                       uint32_t frameIndex, TerrainDebugView view, bool reprojected,
                                       const ImageryBinding* imagery, PassMarks& marks) const {
  DrawStats stats;
  const bool wireframe = view == TerrainDebugView::kWireframe;
  vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
  for (const uint32_t group : kGroupOrder) {
    const uint32_t r = group % kIndexRanges;             // the group's index range
    if (group == 2) marks.write(cmd, kMarkSkirtsBegin);  // kGroupOrder: grids, then from group 2 on skirts
    for (uint32_t page = 0; page < pageCount; ++page) {
      const size_t g = size_t(group) * pageCount + page;
      if (instancesOf_[g] == 0) continue;
      const vk::GraphicsPipeline& pipeline = groupPipeline(group, view);
      const bool cover = style_.coverEverywhere() || (group % kColourGroups >= kDetailGroups && !wireframe);
      const gpu::TerrainDrawPush push{r % 2 == 0 ? cells_ : cells_ / 2, 0};
      std::array<VkDescriptorBufferInfo, 9 + 1> buffers{instanceDescriptor(frameIndex), payloads.window(page),
                                                        constantsDescriptor(frameIndex)};
      size_t count = 3;
      if (reprojected) {
        for (const VkDescriptorBufferInfo& b : {reprojection_[frameIndex].descriptor(), faces_.descriptor()})
          buffers[count++] = b;
      } else if (atmosphere_) {
        for (const VkDescriptorBufferInfo& b :
             {atmosphere_->parameters(), atmosphere_->transmittance(), atmosphere_->irradiance(),
              atmosphere_->scattering(), aerial_->view().camera(frameIndex), aerial_->view().table(frameIndex)})
          buffers[count++] = b;
      }
      if (imagery && !wireframe) buffers[count++] = imagery->cells;  // the wireframe's pipeline has no maps
      const ImageSet images = wireframe ? ImageSet{} : drawImages(payloads, page, imagery, cover);
      pipeline.bind(cmd, std::span(buffers.data(), count), &push, sizeof(push),
                    std::span(images.images.data(), images.count));
      vkCmdDrawIndexed(cmd, count_[r], instancesOf_[g], first_[r], 0, firstInstance_[g]);
      ++stats.drawCalls;
      stats.triangles += uint64_t(count_[r] / 3) * instancesOf_[g];
    }
  }
  return stats;
}

const vk::GraphicsPipeline& TerrainRenderer::groupPipeline(uint32_t group, TerrainDebugView view) const {
  // Grids are drawn with back faces culled, skirts from both sides; the wireframe view shows both.
  // Nodes with sea use the water shader unless a debug view colours them by level.
  if (view == TerrainDebugView::kWireframe) return *wireframe_;
  const SurfacePipelines& set = group >= kColourGroups && coloured_.solid ? coloured_ : plain_;
  group %= kColourGroups;
  const uint32_t r = group % kIndexRanges;
  const bool detail = group >= kDetailGroups;
  if (group % kDetailGroups >= kWaterGroups && set.water && view == TerrainDebugView::kShaded)
    return r >= 2 ? *set.waterSkirts : detail ? *set.waterDetail : *set.water;
  return r >= 2 ? *set.skirts : detail ? *set.solidDetail : *set.solid;
}

TerrainRenderer::ImageSet TerrainRenderer::drawImages(const PayloadPages& payloads, uint32_t page,
                                                      const ImageryBinding* imagery, bool cover) const {
  ImageSet set;
  // The detail textures, for the land cover pipelines.
  if (cover) set.images[set.count++] = {{GLOBE_TERRAIN_DETAIL_BINDING}, style_.detailTextures};
  if (imagery) {
    for (const vk::ImageDescriptor& image : imagery->textures) set.images[set.count++] = image;
  } else if (style_.normalMapScale > 0 && payloads.surfaces) {
    set.images[set.count++] = payloads.surfaces->sampled(page, GLOBE_TERRAIN_SURFACE_BINDING);
  }
  if (shadows_) set.images[set.count++] = shadows_->sampled();
  return set;
}

}  // namespace globe
