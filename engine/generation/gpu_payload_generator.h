#pragma once
// The GPU payload generator: fills payload slots with shaders/payload_generate.comp, asynchronously.
// generate() splits its jobs into batches of at most maxJobsPerSubmit; each batch records one
// dispatch per payload page it writes (one workgroup per node) into its own command buffer and is
// submitted with a fence. collect() polls the fences without waiting and reports the finished
// nodes with their radius ranges (padded for unresolved detail, planet/streaming/payload_reference.h).
// Implements planet's PayloadGenerator, so the PayloadPool drives it exactly like the CPU fake.
// A planet with elevation sources goes through the source I/O thread first
// (planet/streaming/request_preparer.h): generate() only queues there, and the prepared jobs are
// submitted, with their source terms, by later generate()/collect() calls while a batch is free.
#include "engine/generation/payload_pages.h"
#include "engine/generation/surface_textures.h"
#include "engine/vk/compute_pipeline.h"
#include "planet/model/elevation_model.h"
#include "planet/streaming/payload_generator.h"
#include "planet/streaming/request_preparer.h"
#include "shaders/include/payload_layout.h"

#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace globe {

// Arithmetic of payload generation. kDouble is the engine (positions exact to the CPU reference);
// kFloat evaluates the elevation and the planet-centred positions in float, as an all-float engine
// would: only to measure what double buys (`globe trade`, docs/tradeoffs.md).
enum class GenerationPrecision { kDouble, kFloat };

class GpuPayloadGenerator final : public PayloadGenerator {
 public:
  // `cells`: grid cells per node side, a power of two in [8, 256] (gpu::validGridCells).
  // `maxJobsPerSubmit`: most nodes one generate() call takes (the pool's dispatch budget);
  // `maxSubmitsInFlight`: batches that may run at once (the pool's in-flight cap / budget, rounded
  // up).
  // `model` must outlive the generator (job centres are surface points of the CPU reference).
  // `waterSurface`: samples below sea level are placed on the sea surface (the renderer's payloads on
  // a planet with water, ElevationModel::drawsWater); otherwise the ground everywhere (collision
  // meshes, bakes). `normalMapScale`: map cells per grid cell of each payload's normal map (1, 2
  // or 4: the renderer's payloads), 0 = none (collision meshes, bakes).
  GpuPayloadGenerator(vk::Device& device, const ElevationModel& model, uint32_t cells, uint32_t maxJobsPerSubmit,
                      uint32_t maxSubmitsInFlight, GenerationPrecision precision = GenerationPrecision::kDouble,
                      bool waterSurface = false, uint32_t normalMapScale = 0);
  ~GpuPayloadGenerator() override;

  // Allocates the payload buffer for `slots` slots (once, before the first generate()), bound in
  // pages of as many slots as one storage-buffer binding holds (and with maps, as one image array
  // has layers), or `maxSlotsPerPage` if smaller (0 = no extra cap; tests use it to exercise paging),
  // and with normal maps the pages' surface textures.
  void reserveSlots(uint32_t slots, uint32_t maxSlotsPerPage = 0);

  void generate(std::span<const GenerationJob> jobs) override;
  void collect(std::vector<GenerationResult>& finished) override;
  size_t slotBytes() const override { return slotBytesFor(cells_, normalMapScale_, surfaceLayersPerSlot()); }
  std::string lastFailure() const override { return lastFailure_; }
  // Bytes of one slot in the payload buffer: the mesh (payload_layout.h) and the land cover masks.
  static size_t bufferSlotBytes(uint32_t cells) { return size_t(GLOBE_PAYLOAD_SLOT_VEC4(cells)) * 16u; }
  // Bytes of one slot in all: its buffer part and, if normalMapScale > 0, its surface texture layers.
  static size_t slotBytesFor(uint32_t cells, uint32_t normalMapScale = 0, uint32_t layersPerSlot = 1) {
    return bufferSlotBytes(cells) + SurfaceTextures::bytesPerSlot(cells * normalMapScale, layersPerSlot);
  }
  // Surface texture layers per slot: 2 on a planet with an overlay (the colour layer, payload_layout.h).
  uint32_t surfaceLayersPerSlot() const { return normalMapScale_ > 0 && model_.overlay() != nullptr ? 2u : 1u; }

  // Blocks until every submitted batch has finished (converged mode, shutdown, tests).
  void waitIdle();

  // From now on, every batch also copies the first `bytes` of each job's slot into `destination`
  // at slot x bytes, in its own command buffer: once collect() reports a job, its copy is on the
  // host, with no further submission or wait (collision meshes read their positions back this
  // way). `destination` must be host-visible, hold every slot, and outlive the generator.
  void copyToHost(const vk::Buffer& destination, VkDeviceSize bytes);

  uint32_t cells() const { return cells_; }
  uint32_t normalMapScale() const { return normalMapScale_; }
  // Node centre (metres) the payload in `slot` is relative to (the job's snapped centre).
  const glm::dvec3& slotCentre(uint32_t slot) const { return slotCentres_[slot]; }
  // The payload in `slot` has ground below sea level, i.e. water to draw (always false without
  // waterSurface).
  bool slotHasWater(uint32_t slot) const { return slotWater_[slot] != 0; }
  // The slot's fragments read its colour layer: the overlay's hue varies within its cells
  // (overlayNeedsColourLayer, request_preparer.h); false on planets without an overlay.
  bool slotHasColourLayer(uint32_t slot) const { return slotColourLayer_[slot] != 0; }
  // The whole payload buffer (copies, tests) and its binding windows (shaders).
  const vk::Buffer& payloads() const { return payloads_; }
  const PayloadPages& pages() const { return pages_; }
  // The pages' surface textures (one 1 x 1 dummy layer without normal maps).
  const SurfaceTextures& surfaceTextures() const { return textures_; }
  // Device time of all finished batches so far (ms) and how many nodes they held.
  double gpuTime_ms() const { return gpuTime_ms_; }
  uint64_t nodesGenerated() const { return nodesGenerated_; }
  // Planets with sources: the I/O thread (nullptr otherwise), and request -> resident time (s) of
  // every finished job that carried source terms, in finishing order.
  const SourceRequestPreparer* sourcePreparer() const { return preparer_.get(); }
  const std::vector<double>& sourceLatencies_s() const { return sourceLatencies_s_; }

 private:
  struct Batch {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    vk::UniqueFence fence;
    vk::Buffer jobs;
    vk::Buffer results;
    vk::Buffer scratch;
    vk::Buffer sourceTerms;  // S * S dvec4 per job with sources (elevation_sources.glsl)
    vk::Buffer overlay;      // GLOBE_PAYLOAD_OVERLAY_WORDS per job on a planet with an overlay
    std::vector<GenerationJob> submitted;
    // Per job: when its request was queued for the source I/O thread; max() = not read from sources.
    std::vector<std::chrono::steady_clock::time_point> sourceQueued;
    std::vector<double> sourcePad_m;   // per job: sourceDetailPad_m of its terms
    std::vector<uint8_t> colourLayer;  // per job: PreparedRequest::colourLayer
    bool busy = false;
    uint32_t index = 0;  // query slots 2*index, 2*index+1
  };
  // Batch `index`'s command buffer, fence and buffers, sized for maxJobs_ jobs.
  Batch makeBatch(uint32_t index) const;
  Batch& freeBatch();
  Batch* idleBatch();
  // Records and submits `requests` in batches; with mayWait false only while a batch is idle.
  // Removes what it submitted.
  void submitBatches(std::vector<PreparedRequest>& requests, bool mayWait);
  void record(Batch& batch, std::span<PreparedRequest> requests);
  // Overlay words a job takes in a batch (GLOBE_PAYLOAD_OVERLAY_WORDS), and job `job`'s copied in
  // (or zeros when it has none).
  size_t overlayWordsPerJob() const;
  void copyOverlay(Batch& batch, size_t job, const std::vector<std::uint32_t>& words) const;
  void submitPrepared();
  // Submits a recorded batch; a failed submit (not a lost device) reports its jobs failed instead.
  void submit(Batch& batch);
  void finish(Batch& batch, std::vector<GenerationResult>& finished);

  vk::Device& device_;
  const ElevationModel& model_;
  uint32_t cells_;
  uint32_t normalMapScale_;
  uint32_t maxJobs_;
  vk::ComputePipeline pipeline_;
  vk::Buffer elevation_;
  vk::Buffer colourRamp_;
  vk::Buffer landCover_;  // the planet's land cover (gpu::LandCoverParams), binding 8
  vk::Buffer faces_;
  vk::Buffer payloads_;
  PayloadPages pages_;
  SurfaceTextures textures_;
  vk::UniqueCommandPool commandPool_;
  vk::UniqueQueryPool queries_;
  double timestampPeriod_ns_ = 1.0;
  std::vector<Batch> batches_;
  std::vector<glm::dvec3> slotCentres_;
  std::vector<uint8_t> slotWater_;        // per slot: slotHasWater
  std::vector<uint8_t> slotColourLayer_;  // per slot: slotHasColourLayer
  bool waterSurface_ = false;
  std::deque<uint32_t> order_;                   // busy batches, oldest first
  std::vector<GenerationResult> waitedResults_;  // of batches freeBatch() waited for, until collect()
  double gpuTime_ms_ = 0.0;
  uint64_t nodesGenerated_ = 0;
  std::string lastFailure_;
  std::unique_ptr<SourceRequestPreparer> preparer_;
  std::vector<PreparedRequest> prepared_;  // taken from the I/O thread, waiting for an idle batch
  std::vector<double> sourceLatencies_s_;
  const vk::Buffer* hostCopy_ = nullptr;
  VkDeviceSize hostCopyBytes_ = 0;
};

}  // namespace globe
