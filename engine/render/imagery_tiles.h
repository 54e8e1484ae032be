#pragma once
// Imagery LOD's engine side [Rodrigues 2016, §3.2]: the surface tiles (normal and colour maps of
// GLOBE_IMAGERY_TILE_CELLS cells a side, payload_layout.h) have their own generator, their own pool
// (budget, request queue, eviction) and their own selection by texel magnification
// (planet/imagery/imagery_selection.h), run every frame after the mesh's. The drawn nodes' cell
// tables go to the GPU in one host-visible buffer per frame in flight; the _imagery fragment stages
// sample the tile of each fragment's cell (terrain_fragment.glsl).
#include "engine/generation/gpu_payload_generator.h"
#include "engine/vk/resources.h"
#include "planet/camera/camera.h"
#include "planet/imagery/imagery_selection.h"
#include "planet/model/elevation_model.h"
#include "planet/streaming/payload_pool.h"

#include <array>
#include <memory>
#include <span>

namespace globe {

// Payload pages of the tiles (each a surface texture array of at most maxImageArrayLayers tiles, and
// a window of at most one storage-buffer binding) the fragment stages bind (GLOBE_IMAGERY_TILE_PAGES).
inline constexpr uint32_t kImageryTilePages = 4;

struct ImagerySettings {
  double magnification_px = 1.5;  // most screen pixels one texel may cover
  // The tiles' payload slots (capped at kImageryTilePages bindings' worth). The 2 m camera at 1280x720
  // draws 1311 tiles (211 KiB each) and converges in 512 MiB, not in 384 (docs/rendering.md).
  double vramBudget_MiB = 512.0;
  // Slots per page (binding window), rounded down to a multiple of 16; 0: as many as one binding
  // holds. Fewer spread a small pool over every page (the tests).
  uint32_t slotsPerPage = 0;
};

// What the terrain pipelines bind for imagery: the frame's cell tables (GLOBE_TERRAIN_IMAGERY_BINDING)
// and the tiles' pages' surface textures (GLOBE_TERRAIN_SURFACE_BINDING on; unused pages repeat the first).
struct ImageryBinding {
  VkDescriptorBufferInfo cells{};
  std::array<vk::ImageDescriptor, kImageryTilePages> textures{};
};

class ImageryTiles {
 public:
  // Errors: a budget too small for the 30 roots and a working set.
  static Result<std::unique_ptr<ImageryTiles>> create(vk::Device& device, const ElevationModel& model,
                                                      const ImagerySettings& settings, const StreamingConfig& streaming,
                                                      GenerationPrecision precision, int maxLevel);
  ~ImageryTiles();

  // One frame, after the mesh's selection (`nodes`, whose known radius ranges `geometry` gives):
  // collects finished tiles, selects, requests, pins the drawn tiles, starts generations.
  // `nearest_m`: the camera's height above the ground below it; `requestAllRoots`: the warm-up.
  void update(uint64_t frame, uint64_t completedFrame, const Camera& camera, double nearest_m, double pixelsPerRadian,
              std::span<const SelectedNode> nodes, const NodeResidency& geometry, bool requestAllRoots);
  // Writes the last update's cell tables (kImageryCellsPerNode per node, in its order) into frame
  // `frameIndex`'s buffer; the caller waited for that frame's previous use.
  ImageryBinding write(uint32_t frameIndex);

  // Nothing asked for, queued or being made.
  bool converged() const;
  void waitIdle() { generator_->waitIdle(); }
  const ImageryStats& stats() const { return selection_.stats; }
  const PayloadPool& pool() const { return *pool_; }
  const GpuPayloadGenerator& generator() const { return *generator_; }
  const ImagerySelector& selector() const { return selector_; }
  double gpuTime_ms() const { return generator_->gpuTime_ms(); }

 private:
  ImageryTiles(vk::Device& device, const ElevationModel& model, const ImagerySettings& settings,
               const StreamingConfig& streaming, GenerationPrecision precision, int maxLevel);
  // The GPU record of a drawn node's cell.
  void cellRecord(const NodeId& node, const ImageryCell& cell, void* out) const;

  vk::Device& device_;
  ImagerySelector selector_;
  std::unique_ptr<GpuPayloadGenerator> generator_;
  std::unique_ptr<PayloadPool> pool_;
  ImagerySelection selection_;
  std::vector<NodeId> nodes_;        // the last update's drawn nodes
  std::array<vk::Buffer, 2> cells_;  // per frame in flight
};

}  // namespace globe
