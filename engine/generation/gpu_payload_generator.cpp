#include "engine/generation/gpu_payload_generator.h"

#include "engine/vk/resources.h"
#include "engine/vk/submit_faults.h"
#include "engine/vk/vk_check.h"
#include "engine/vk/vk_create.h"
#include "planet/geometry/face_mapping.h"
#include "planet/streaming/payload_reference.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace globe {
namespace {

// The elevation kernel's constants, then the water-surface switch (GLOBE_PAYLOAD_SPEC_WATER_SURFACE),
// the normal map's scale (GLOBE_PAYLOAD_SPEC_NORMAL_MAP_SCALE), the land cover switch and the overlay's.
std::array<uint32_t, GLOBE_PAYLOAD_SPEC_OVERLAY + 1> payloadSpecialization(const ElevationModel& model,
                                                                           bool waterSurface, uint32_t normalMapScale) {
  static_assert(GLOBE_PAYLOAD_SPEC_WATER_SURFACE == GLOBE_ELEVATION_SPEC_COUNT);
  static_assert(GLOBE_PAYLOAD_SPEC_NORMAL_MAP_SCALE == GLOBE_PAYLOAD_SPEC_WATER_SURFACE + 1);
  static_assert(GLOBE_PAYLOAD_SPEC_LAND_COVER == GLOBE_PAYLOAD_SPEC_NORMAL_MAP_SCALE + 1);
  static_assert(GLOBE_PAYLOAD_SPEC_OVERLAY == GLOBE_PAYLOAD_SPEC_LAND_COVER + 1);
  std::array<uint32_t, GLOBE_PAYLOAD_SPEC_OVERLAY + 1> values{};
  const ElevationSpecialization elevation = elevationSpecialization(model.params());
  std::copy(elevation.begin(), elevation.end(), values.begin());
  values[GLOBE_PAYLOAD_SPEC_WATER_SURFACE] = waterSurface && model.drawsWater() ? 1u : 0u;
  values[GLOBE_PAYLOAD_SPEC_NORMAL_MAP_SCALE] = normalMapScale;
  values[GLOBE_PAYLOAD_SPEC_LAND_COVER] = model.landCover().class_count > 0 ? 1u : 0u;
  values[GLOBE_PAYLOAD_SPEC_OVERLAY] = model.overlay() != nullptr ? 1u : 0u;
  return values;
}

// The surface texture's storage images (payload_layout.h's bindings): mip 0, mip 1.
constexpr std::array<vk::ImageSlot, 2> kSurfaceStorageSlots{
    vk::ImageSlot{GLOBE_PAYLOAD_SURFACE_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
    vk::ImageSlot{GLOBE_PAYLOAD_PARENT_SURFACE_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};

}  // namespace

GpuPayloadGenerator::GpuPayloadGenerator(vk::Device& device, const ElevationModel& model, uint32_t cells,
                                         uint32_t maxJobsPerSubmit, uint32_t maxSubmitsInFlight,
                                         GenerationPrecision precision, bool waterSurface, uint32_t normalMapScale)
    : device_(device),
      model_(model),
      cells_(cells),
      normalMapScale_(normalMapScale),
      maxJobs_(std::min<uint32_t>(maxJobsPerSubmit, GLOBE_PAYLOAD_MAX_BATCH)),
      pipeline_(device,
                precision == GenerationPrecision::kFloat ? "payload_generate_float.comp" : "payload_generate.comp", 10,
                2 * sizeof(uint32_t), /*uniformMask=*/(1u << 0) | (1u << 7) | (1u << 8),
                payloadSpecialization(model, waterSurface, normalMapScale), kSurfaceStorageSlots),
      elevation_(device, sizeof(gpu::ElevationParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::HostVisible,
                 "elevation params"),
      colourRamp_(device, sizeof(gpu::ColourRampParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::HostVisible,
                  "colour ramp"),
      landCover_(device, sizeof(gpu::LandCoverParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::HostVisible,
                 "land cover"),
      faces_(device, 30 * sizeof(FaceCornersGpu), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible,
             "face corners") {
  if (!gpu::validGridCells(cells))
    throw std::runtime_error("grid cells must be a power of two in [8, 256], got " + std::to_string(cells));
  if (!gpu::validNormalMapScale(normalMapScale))
    throw std::runtime_error("normal map scale must be 0, 1, 2, 4 or 8, got " + std::to_string(normalMapScale));
  std::memcpy(elevation_.mapped(), &model.params(), sizeof(gpu::ElevationParams));
  std::memcpy(colourRamp_.mapped(), &model.colourRamp(), sizeof(gpu::ColourRampParams));
  std::memcpy(landCover_.mapped(), &model.landCover(), sizeof(gpu::LandCoverParams));
  waterSurface_ = waterSurface && model.drawsWater();
  auto* faces = static_cast<FaceCornersGpu*>(faces_.mapped());
  for (int f = 0; f < 30; ++f) faces[f] = RhombusFaceMapping::get().gpuCorners(f);

  commandPool_ =
      vk::createCommandPool(device.device(), device.queueFamily(), VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT);

  uint32_t batchCount = std::max<uint32_t>(maxSubmitsInFlight, 1) + 1;
  queries_ = vk::createTimestampQueryPool(device.device(), 2 * batchCount);
  vkResetQueryPool(device.device(), queries_, 0, 2 * batchCount);
  timestampPeriod_ns_ = double(device.properties().limits.timestampPeriod);

  batches_.resize(batchCount);
  for (uint32_t b = 0; b < batchCount; ++b) batches_[b] = makeBatch(b);
  if (model.sources() != nullptr || model.overlay() != nullptr)
    preparer_ = std::make_unique<SourceRequestPreparer>(model, cells, waterSurface_, normalMapScale);
}

GpuPayloadGenerator::Batch GpuPayloadGenerator::makeBatch(uint32_t index) const {
  const size_t samples = size_t(cells_ + 3) * size_t(cells_ + 3);
  // The scratch holds a job's double positions: the mesh samples, then (reused) the normal map's grids.
  const size_t scratchPerJob = std::max(samples, size_t(GLOBE_SURFACE_EVALUATIONS(cells_ * normalMapScale_)));
  Batch batch;
  batch.index = index;
  batch.cmd = vk::allocateCommandBuffer(device_.device(), commandPool_);
  batch.fence = vk::createFence(device_.device());
  batch.jobs = vk::Buffer(device_, maxJobs_ * sizeof(gpu::PayloadJob), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                          vk::MemoryUse::HostVisible, "payload jobs");
  batch.results = vk::Buffer(device_, maxJobs_ * sizeof(gpu::PayloadResult), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                             vk::MemoryUse::HostVisible, "payload results");
  batch.scratch = vk::Buffer(device_, VkDeviceSize(maxJobs_) * scratchPerJob * 32, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                             vk::MemoryUse::DeviceLocal, "payload scratch");
  // A planet without sources binds a one-term buffer it never reads.
  const VkDeviceSize termBytes = model_.sources() != nullptr ? VkDeviceSize(maxJobs_) * samples * 32 : 32;
  batch.sourceTerms = vk::Buffer(device_, termBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible,
                                 "payload source terms");
  // Likewise a planet without an overlay binds one word it never reads.
  const VkDeviceSize overlayBytes = model_.overlay() != nullptr ? VkDeviceSize(maxJobs_) * overlayWordsPerJob() * 4 : 4;
  batch.overlay = vk::Buffer(device_, overlayBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::HostVisible,
                             "payload overlay colours");
  batch.submitted.reserve(maxJobs_);
  return batch;
}

GpuPayloadGenerator::~GpuPayloadGenerator() {
  // A lost device fails the wait: its work is over then, and a destructor must not throw.
  try {
    waitIdle();
  } catch (const vk::VulkanError&) {
  }
}

void GpuPayloadGenerator::reserveSlots(uint32_t slots, uint32_t maxSlotsPerPage) {
  assert(payloads_.size() == 0);
  const VkDeviceSize bytesPerSlot = bufferSlotBytes(cells_);
  payloads_ = vk::Buffer(device_, VkDeviceSize(slots) * bytesPerSlot,
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                         vk::MemoryUse::DeviceLocal, "payload slots");
  const VkPhysicalDeviceLimits& limits = device_.properties().limits;
  uint32_t perPage = std::max<uint32_t>(1, uint32_t(limits.maxStorageBufferRange / bytesPerSlot));
  // A page's surface textures are one array image: a layer per slot.
  if (normalMapScale_ > 0) perPage = std::min(perPage, limits.maxImageArrayLayers / surfaceLayersPerSlot());
  if (maxSlotsPerPage > 0) perPage = std::min(perPage, maxSlotsPerPage);
  // Every window must start at a multiple of the storage-buffer offset alignment (slot bytes are a
  // multiple of 16 and the alignment a power of two <= 256, so 16 slots always align).
  while (perPage > 1 && (VkDeviceSize(perPage) * bytesPerSlot) % limits.minStorageBufferOffsetAlignment != 0) --perPage;
  if (slots > perPage && (VkDeviceSize(perPage) * bytesPerSlot) % limits.minStorageBufferOffsetAlignment != 0)
    throw std::runtime_error("payload pages of " + std::to_string(perPage) +
                             " slots break the storage-buffer offset alignment");
  textures_ = SurfaceTextures(device_, cells_ * normalMapScale_, slots, perPage, surfaceLayersPerSlot());
  pages_ = {payloads_.handle(), payloads_.size(), VkDeviceSize(perPage) * bytesPerSlot, perPage,
            normalMapScale_ > 0 ? &textures_ : nullptr};
  slotCentres_.assign(slots, glm::dvec3(0.0));
  slotWater_.assign(slots, 0);
  slotColourLayer_.assign(slots, 0);
}

GpuPayloadGenerator::Batch& GpuPayloadGenerator::freeBatch() {
  for (Batch& b : batches_)
    if (!b.busy) return b;
  // Every batch is running (one generate() call longer than the in-flight cap): wait for the oldest
  // and reuse it; its results wait for the next collect().
  Batch& oldest = batches_[order_.front()];
  VkFence fence = oldest.fence;
  GLOBE_VK_CHECK(vkWaitForFences(device_.device(), 1, &fence, VK_TRUE, UINT64_MAX));
  order_.pop_front();
  finish(oldest, waitedResults_);
  return oldest;
}

GpuPayloadGenerator::Batch* GpuPayloadGenerator::idleBatch() {
  for (Batch& b : batches_)
    if (!b.busy) return &b;
  return nullptr;
}

void GpuPayloadGenerator::generate(std::span<const GenerationJob> jobs) {
  assert(payloads_.size() > 0 && "reserveSlots() first");
  if (preparer_) {
    preparer_->submit(jobs);
    submitPrepared();
    return;
  }
  std::vector<PreparedRequest> requests;
  requests.reserve(jobs.size());
  for (const GenerationJob& job : jobs)
    requests.push_back({job, makePayloadJob(job.node, job.slot, model_, waterSurface_), {}, {}});
  submitBatches(requests, true);
}

void GpuPayloadGenerator::submitPrepared() {
  preparer_->takeReady(prepared_, SIZE_MAX);
  submitBatches(prepared_, false);
}

void GpuPayloadGenerator::submitBatches(std::vector<PreparedRequest>& requests, bool mayWait) {
  size_t first = 0;
  while (first < requests.size()) {
    Batch* batch = mayWait ? &freeBatch() : idleBatch();
    if (batch == nullptr) break;  // the rest waits for the next call: the frame never waits here
    const size_t count = std::min<size_t>(maxJobs_, requests.size() - first);
    record(*batch, std::span(requests).subspan(first, count));
    first += count;
  }
  requests.erase(requests.begin(), requests.begin() + std::ptrdiff_t(first));
}

size_t GpuPayloadGenerator::overlayWordsPerJob() const {
  return GLOBE_PAYLOAD_OVERLAY_WORDS(cells_, cells_ * normalMapScale_);
}

void GpuPayloadGenerator::copyOverlay(Batch& batch, size_t job, const std::vector<std::uint32_t>& words) const {
  if (model_.overlay() == nullptr) return;
  auto* to = static_cast<std::uint32_t*>(batch.overlay.mapped()) + job * overlayWordsPerJob();
  // A job the overlay does not touch (or a request made without the I/O thread) blends nothing.
  if (words.size() == overlayWordsPerJob())
    std::memcpy(to, words.data(), words.size() * sizeof(std::uint32_t));
  else
    std::memset(to, 0, overlayWordsPerJob() * sizeof(std::uint32_t));
}

void GpuPayloadGenerator::record(Batch& batch, std::span<PreparedRequest> requests) {
  const size_t count = requests.size();
  const size_t samples = size_t(cells_ + 3) * size_t(cells_ + 3);
  auto* gpuJobs = static_cast<gpu::PayloadJob*>(batch.jobs.mapped());
  auto* terms = static_cast<glm::dvec4*>(batch.sourceTerms.mapped());
  // One dispatch per payload page the batch writes (usually one): jobs sorted by page, each
  // dispatch offset to its first job (vkCmdDispatchBase) with its page's window bound.
  std::stable_sort(requests.begin(), requests.end(), [&](const PreparedRequest& a, const PreparedRequest& b) {
    return pages_.page(a.request.slot) < pages_.page(b.request.slot);
  });
  batch.submitted.clear();
  batch.sourceQueued.clear();
  batch.sourcePad_m.clear();
  batch.colourLayer.clear();
  for (size_t k = 0; k < count; ++k) {
    const PreparedRequest& r = requests[k];
    batch.submitted.push_back(r.request);
    gpuJobs[k] = r.job;
    gpuJobs[k].slot = pages_.localSlot(r.request.slot);
    const bool hasTerms = !r.terms.empty();
    gpuJobs[k].sourceBase = hasTerms ? uint32_t(k * samples) : GLOBE_NO_SOURCE_TERMS;
    if (hasTerms) std::memcpy(terms + k * samples, r.terms.data(), samples * sizeof(glm::dvec4));
    copyOverlay(batch, k, r.overlay);
    const bool prepared = hasTerms || !r.overlay.empty();
    batch.sourceQueued.push_back(prepared ? r.queued : std::chrono::steady_clock::time_point::max());
    batch.sourcePad_m.push_back(sourceDetailPad_m(r.terms));
    batch.colourLayer.push_back(r.colourLayer ? 1 : 0);
    slotCentres_[r.request.slot] = {gpuJobs[k].centre.x, gpuJobs[k].centre.y, gpuJobs[k].centre.z};
  }

  GLOBE_VK_CHECK(vkResetCommandBuffer(batch.cmd, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  GLOBE_VK_CHECK(vkBeginCommandBuffer(batch.cmd, &begin));
  vkCmdWriteTimestamp2(batch.cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, queries_, 2 * batch.index);
  uint32_t push[2] = {cells_, uint32_t(count)};
  for (size_t run = 0; run < count;) {
    const uint32_t page = pages_.page(batch.submitted[run].slot);
    size_t end = run + 1;
    while (end < count && pages_.page(batch.submitted[end].slot) == page) ++end;
    pipeline_.bind(batch.cmd,
                   {elevation_.descriptor(), faces_.descriptor(), batch.jobs.descriptor(), pages_.window(page),
                    batch.scratch.descriptor(), batch.results.descriptor(), batch.sourceTerms.descriptor(),
                    colourRamp_.descriptor(), landCover_.descriptor(), batch.overlay.descriptor()},
                   push, sizeof(push), textures_.storage(normalMapScale_ > 0 ? page : 0));
    vkCmdDispatchBase(batch.cmd, uint32_t(run), 0, 0, uint32_t(end - run), 1, 1);
    run = end;
  }
  vk::computeWriteBarrier(batch.cmd);
  vkCmdWriteTimestamp2(batch.cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, queries_, 2 * batch.index + 1);
  if (hostCopy_) {
    std::vector<VkBufferCopy> regions;
    for (const GenerationJob& job : batch.submitted)
      regions.push_back(
          {VkDeviceSize(job.slot) * bufferSlotBytes(cells_), VkDeviceSize(job.slot) * hostCopyBytes_, hostCopyBytes_});
    vkCmdCopyBuffer(batch.cmd, pages_.buffer, hostCopy_->handle(), uint32_t(regions.size()), regions.data());
    vk::hostReadBarrier(batch.cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  }
  GLOBE_VK_CHECK(vkEndCommandBuffer(batch.cmd));
  submit(batch);
}

void GpuPayloadGenerator::copyToHost(const vk::Buffer& destination, VkDeviceSize bytes) {
  assert(bytes <= bufferSlotBytes(cells_) && destination.size() >= VkDeviceSize(slotCentres_.size()) * bytes);
  hostCopy_ = &destination;
  hostCopyBytes_ = bytes;
}

void GpuPayloadGenerator::submit(Batch& batch) {
  VkFence fence = batch.fence;
  GLOBE_VK_CHECK(vkResetFences(device_.device(), 1, &fence));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &batch.cmd;
  try {
    GLOBE_VK_SUBMIT(vk::SubmitSite::kGeneration, vkQueueSubmit(device_.queue(), 1, &submit, fence));
  } catch (const vk::VulkanError& e) {
    if (e.result() == VK_ERROR_DEVICE_LOST) throw;  // nothing runs any more: the caller stops
    // Out of memory, say: nothing was submitted. The jobs come back failed with the next collect(),
    // the pool asks again later, and the view draws their parents meanwhile.
    for (const GenerationJob& job : batch.submitted) waitedResults_.push_back({job.node, job.slot, {}, true});
    lastFailure_ = e.what();
    batch.submitted.clear();
    return;
  }
  batch.busy = true;
  order_.push_back(batch.index);
}

void GpuPayloadGenerator::finish(Batch& batch, std::vector<GenerationResult>& finished) {
  const auto* results = static_cast<const gpu::PayloadResult*>(batch.results.mapped());
  const auto now = std::chrono::steady_clock::now();
  for (size_t k = 0; k < batch.submitted.size(); ++k) {
    if (batch.sourceQueued[k] != std::chrono::steady_clock::time_point::max())
      sourceLatencies_s_.push_back(std::chrono::duration<double>(now - batch.sourceQueued[k]).count());
    const GenerationJob& job = batch.submitted[k];
    RadiusRange payload{results[k].minRadius_m, results[k].maxRadius_m};
    // A payload whose radii are not finite (a broken device or driver) is not drawn: bounds from it
    // would break culling and the LOD ranges.
    const double error_m = results[k].geometricError_m;
    if (!(std::isfinite(payload.min_m) && std::isfinite(payload.max_m) && payload.min_m <= payload.max_m &&
          std::isfinite(error_m) && error_m >= 0.0)) {
      finished.push_back({job.node, job.slot, {}, true});
      lastFailure_ = "payload radius range or geometric error not finite";
      continue;
    }
    RadiusRange padded = paddedRadiusRange(model_.params(), payload, job.node.level, cells_);
    padded.min_m = std::max(0.0, padded.min_m - batch.sourcePad_m[k]);
    padded.max_m += batch.sourcePad_m[k];
    slotWater_[job.slot] = waterSurface_ && results[k].lowestElevation_m < model_.seaLevel_m() ? 1 : 0;
    slotColourLayer_[job.slot] = batch.colourLayer[k];
    finished.push_back({job.node, job.slot, padded, false, error_m});
  }
  uint64_t stamps[2] = {0, 0};
  VkResult r = vkGetQueryPoolResults(device_.device(), queries_, 2 * batch.index, 2, sizeof(stamps), stamps,
                                     sizeof(uint64_t), VK_QUERY_RESULT_64_BIT);
  if (r == VK_SUCCESS && stamps[1] >= stamps[0])
    gpuTime_ms_ += double(stamps[1] - stamps[0]) * timestampPeriod_ns_ * 1e-6;
  vkResetQueryPool(device_.device(), queries_, 2 * batch.index, 2);
  nodesGenerated_ += batch.submitted.size();
  batch.submitted.clear();
  batch.busy = false;
}

void GpuPayloadGenerator::collect(std::vector<GenerationResult>& finished) {
  if (preparer_) submitPrepared();
  // Batches freeBatch() finished early come first: they were submitted first.
  finished.insert(finished.end(), waitedResults_.begin(), waitedResults_.end());
  waitedResults_.clear();
  // Batches finish in submission order on one queue: stop at the first that is still running.
  while (!order_.empty()) {
    Batch& batch = batches_[order_.front()];
    VkResult status = vkGetFenceStatus(device_.device(), batch.fence);
    if (status == VK_NOT_READY) break;
    GLOBE_VK_CHECK(status);
    order_.pop_front();
    finish(batch, finished);
  }
}

void GpuPayloadGenerator::waitIdle() {
  // Outside the frame loop only (warm-up, converged frames, shutdown): the I/O thread's queue first.
  while (preparer_ && (preparer_->pending() > 0 || !prepared_.empty())) {
    preparer_->waitUntilIdle();
    preparer_->takeReady(prepared_, SIZE_MAX);
    submitBatches(prepared_, true);
  }
  for (uint32_t index : order_) {
    VkFence fence = batches_[index].fence;
    GLOBE_VK_CHECK(vkWaitForFences(device_.device(), 1, &fence, VK_TRUE, UINT64_MAX));
  }
}

}  // namespace globe
