#include "engine/collision/gpu_collision_mesh_source.h"

#include "engine/vk/resources.h"
#include "shaders/include/payload_layout.h"

#include <algorithm>
#include <cassert>

namespace globe {

namespace {

VkDeviceSize positionBlockBytes(uint32_t cells) {
  const VkDeviceSize samples = GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells);
  return samples * samples * sizeof(glm::vec4);
}

}  // namespace

GpuCollisionMeshSource::GpuCollisionMeshSource(vk::Device& device, const ElevationModel& model, uint32_t cells,
                                               uint32_t maxInFlight, uint32_t latencySteps)
    : device_(device),
      generator_(device, model, cells, std::min<uint32_t>(maxInFlight, GLOBE_PAYLOAD_MAX_BATCH), 4),
      syncSlot_(maxInFlight),
      latencySteps_(latencySteps),
      readback_(device, VkDeviceSize(maxInFlight + 1) * positionBlockBytes(cells), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                vk::MemoryUse::HostVisible, "collision mesh readback") {
  generator_.reserveSlots(maxInFlight + 1);
  // Each batch copies its positions to readback_ itself: a finished fence means the mesh is on the
  // host, so collecting never submits or waits (a copy of its own would wait behind every batch
  // queued after the finished ones).
  generator_.copyToHost(readback_, positionBlockBytes(cells));
  for (uint32_t s = maxInFlight; s-- > 0;) freeSlots_.push_back(s);
}

GpuCollisionMeshSource::~GpuCollisionMeshSource() { generator_.waitIdle(); }

void GpuCollisionMeshSource::generate(std::span<const NodeId> nodes) {
  std::vector<GenerationJob> jobs;
  for (const NodeId& node : nodes) {
    assert(!freeSlots_.empty() && "more generations than maxInFlight");
    const uint32_t slot = freeSlots_.back();
    freeSlots_.pop_back();
    jobs.push_back({node, slot});
    jobs_.push_back({node, slot, collects_ + std::max<uint32_t>(latencySteps_, 1), false});
  }
  if (!jobs.empty()) generator_.generate(jobs);
}

void GpuCollisionMeshSource::poll() {
  results_.clear();
  generator_.collect(results_);
  for (const GenerationResult& r : results_) {
    if (r.slot == syncSlot_) continue;
    for (Job& job : jobs_)
      if (job.slot == r.slot && !job.done) job.done = true;
  }
}

CollisionMesh GpuCollisionMeshSource::meshFromReadback(const NodeId& node, uint32_t slot) const {
  const size_t samples = GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells());
  const auto* block = static_cast<const glm::vec4*>(readback_.mapped()) + size_t(slot) * samples * samples;
  return collisionMeshFromPayload(node, generator_.slotCentre(slot), cells(),
                                  std::span<const glm::vec4>(block, samples * samples));
}

void GpuCollisionMeshSource::collect(std::vector<CollisionMesh>& finished) {
  ++collects_;
  poll();
  // Deterministic hand-out: whatever is due now is waited for, and only what is due is handed out.
  const bool deterministic = latencySteps_ > 0;
  if (deterministic &&
      std::any_of(jobs_.begin(), jobs_.end(), [&](const Job& j) { return !j.done && j.collectBy <= collects_; })) {
    generator_.waitIdle();
    poll();
  }
  while (!jobs_.empty() && jobs_.front().collectBy <= collects_ && jobs_.front().done) {
    finished.push_back(meshFromReadback(jobs_.front().node, jobs_.front().slot));
    freeSlots_.push_back(jobs_.front().slot);
    jobs_.pop_front();
  }
}

void GpuCollisionMeshSource::finishAll() {
  generator_.waitIdle();
  // Due at once: the next collect() hands them out whatever latencySteps says.
  for (Job& job : jobs_) job.collectBy = std::min(job.collectBy, collects_ + 1);
}

CollisionMesh GpuCollisionMeshSource::generateNow(const NodeId& node) {
  const GenerationJob job{node, syncSlot_};
  generator_.generate(std::span<const GenerationJob>(&job, 1));
  // On one in-order queue (lavapipe) the job runs after every batch queued before it anyway.
  generator_.waitIdle();
  poll();
  return meshFromReadback(node, syncSlot_);
}

}  // namespace globe
