#include "engine/render/imagery_tiles.h"

#include "engine/vk/vk_check.h"
#include "shaders/include/payload_layout.h"
#include "shaders/include/terrain_layout.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>

namespace globe {

namespace {
// Tiles' slot layout: a grid-32 payload with normal map scale 4 (the mesh part is generated too:
// its samples are the ring the map's border normals are differenced from).
constexpr uint32_t kTileGrid = GLOBE_IMAGERY_TILE_GRID;
constexpr uint32_t kTileMapScale = GLOBE_IMAGERY_TILE_MAP_SCALE;
static_assert(kImageryTilePages == GLOBE_IMAGERY_TILE_PAGES);
static_assert(kImageryCellsPerSide == int(GLOBE_IMAGERY_CELLS_PER_SIDE));
}  // namespace

Result<std::unique_ptr<ImageryTiles>> ImageryTiles::create(vk::Device& device, const ElevationModel& model,
                                                           const ImagerySettings& settings,
                                                           const StreamingConfig& streaming,
                                                           GenerationPrecision precision, int maxLevel) {
  if (!(std::isfinite(settings.magnification_px) && settings.magnification_px > 0.0))
    return Error::inField("texel_magnification", "must be a finite number of pixels > 0");
  std::unique_ptr<ImageryTiles> tiles(new ImageryTiles(device, model, settings, streaming, precision, maxLevel));
  StreamingConfig config = streaming;
  config.vramBudget_MiB = settings.vramBudget_MiB;
  config.ramBudget_MiB = 16.0;
  // Its own budget (--imagery-mib on the command line), named apart from the mesh pool's.
  config.vramBudgetField = "imagery_vram_budget_mib";
  config.vramBudgetName = "the imagery budget (at most " + std::to_string(kImageryTilePages) + " pages' worth)";
  // The fragment stages bind kImageryTilePages pages: surface texture arrays of at most
  // maxImageArrayLayers layers (and buffer windows of at most one binding).
  const VkPhysicalDeviceLimits& limits = device.properties().limits;
  // Pages of a multiple of 16 slots start at an aligned offset (GpuPayloadGenerator::reserveSlots).
  VkDeviceSize perBinding = std::min<VkDeviceSize>(
      limits.maxStorageBufferRange / GpuPayloadGenerator::bufferSlotBytes(kTileGrid), limits.maxImageArrayLayers);
  if (settings.slotsPerPage > 0) perBinding = std::min<VkDeviceSize>(perBinding, settings.slotsPerPage);
  const uint32_t perPage = std::max(uint32_t(perBinding) / 16u * 16u, 16u);
  config.maxSlots = perPage * kImageryTilePages;
  auto pool = PayloadPool::create(config, *tiles->generator_, model.radius_m());
  if (!pool) return pool.error();
  tiles->pool_ = std::move(*pool);
  tiles->generator_->reserveSlots(tiles->pool_->slotCapacity(), perPage);
  assert(tiles->generator_->pages().pageCount() <= kImageryTilePages);
  return tiles;
}

ImageryTiles::ImageryTiles(vk::Device& device, const ElevationModel& model, const ImagerySettings& settings,
                           const StreamingConfig& streaming, GenerationPrecision precision, int maxLevel)
    : device_(device),
      selector_(ImageryConfig{GLOBE_IMAGERY_TILE_CELLS, settings.magnification_px, maxLevel}, model.radius_m(),
                model.bounds().min_m, model.bounds().max_m, model.shape()) {
  generator_ =
      std::make_unique<GpuPayloadGenerator>(device, model, kTileGrid, streaming.dispatchBudget, streaming.maxInFlight,
                                            precision, /*waterSurface=*/true, kTileMapScale);
}

ImageryTiles::~ImageryTiles() {
  try {
    if (generator_) generator_->waitIdle();
  } catch (const vk::VulkanError&) {
  }
}

void ImageryTiles::update(uint64_t frame, uint64_t completedFrame, const Camera& camera, double nearest_m,
                          double pixelsPerRadian, std::span<const SelectedNode> nodes, const NodeResidency& geometry,
                          bool requestAllRoots) {
  pool_->beginFrame(frame, camera.position_m, completedFrame);
  selector_.select(camera.position_m, nearest_m, pixelsPerRadian, nodes, geometry, *pool_, selection_);
  nodes_.resize(nodes.size());
  for (size_t k = 0; k < nodes.size(); ++k) nodes_[k] = nodes[k].id;
  if (requestAllRoots) pool_->requestRoots(glm::length(camera.position_m));
  pool_->markUsed(selection_.tiles);
  pool_->dispatch();
}

void ImageryTiles::cellRecord(const NodeId& node, const ImageryCell& cell, void* out) const {
  gpu::TerrainImageryCell record{};
  if (std::optional<uint32_t> slot = cell.resident ? pool_->slotOf(cell.tile) : std::nullopt) {
    // The tile's layer in its page's surface textures.
    const PayloadPages& pages = generator_->pages();
    record.tile = {pages.localSlot(*slot), 1u, pages.page(*slot), 0u};
    // tile (u, v) = node (u, v) * s + offset, s = 2^(tile level - node level): exact in double.
    const double s = std::ldexp(1.0, int(cell.tile.level) - int(node.level));
    record.map = {
        float(s), float(double(node.x) * s - double(cell.tile.x)), float(double(node.y) * s - double(cell.tile.y)),
        cell.tile.level > 0 ? float(1.0 / selector_.adequateFrom_m(cell.tile.level - 1, selector_.pixelsPerRadian()))
                            : 0.0f};
  }
  std::memcpy(out, &record, sizeof(record));
}

ImageryBinding ImageryTiles::write(uint32_t frameIndex) {
  const VkDeviceSize bytes = std::max<VkDeviceSize>(selection_.cells.size(), 1) * sizeof(gpu::TerrainImageryCell);
  vk::Buffer& buffer = cells_[frameIndex];
  if (buffer.size() < bytes) {
    // The caller waited for this frame index: the old buffer is idle. Grown by half again at least.
    buffer = vk::Buffer(device_, std::max(bytes, buffer.size() + buffer.size() / 2), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        vk::MemoryUse::HostVisible, "imagery cells");
  }
  auto* out = static_cast<unsigned char*>(buffer.mapped());
  gpu::TerrainImageryCell record{};  // built here, not read back from the (write-combined) mapping
  for (size_t k = 0; k < nodes_.size(); ++k)
    for (size_t c = 0; c < size_t(kImageryCellsPerNode); ++c) {
      const size_t i = k * kImageryCellsPerNode + c;
      const ImageryCell& cell = selection_.cells[i];
      const ImageryCell* previous = c > 0 ? &selection_.cells[i - 1] : nullptr;
      // A record depends only on the node and the cell's tile: most cells of a node share one.
      if (!previous || previous->resident != cell.resident || previous->tile.key() != cell.tile.key())
        cellRecord(nodes_[k], cell, &record);
      std::memcpy(out + i * sizeof(record), &record, sizeof(record));
    }
  ImageryBinding binding{buffer.descriptor(), {}};
  const SurfaceTextures& textures = generator_->surfaceTextures();
  for (uint32_t p = 0; p < kImageryTilePages; ++p)
    binding.textures[p] = textures.sampled(p < textures.pageCount() ? p : 0u, GLOBE_TERRAIN_SURFACE_BINDING + p);
  return binding;
}

bool ImageryTiles::converged() const {
  const StreamingStats& s = pool_->stats();
  return selection_.stats.requests == 0 && s.inFlight == 0 && s.queueLength == 0;
}

}  // namespace globe
