#pragma once
// Collision meshes from the GPU payload kernel (shaders/payload_generate.comp, fp64): the same
// dispatch that fills render payloads, into a small slot buffer of its own; each batch then copies
// only the position block of its slots (GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells)^2 vec4s, no normals)
// into a host-visible buffer in its own command buffer, and a finished one is widened into a
// CollisionMesh without another submission. The meshes are therefore bit-
// identical to what the renderer draws at that level, seams included.
//
// collect() hands out finished generations in submission order without waiting (`latencySteps` 0,
// the default: a slow GPU never stalls a physics step), or, with `latencySteps` N >= 1, exactly the
// generations started N collect() calls ago, waiting for their fences if needed: then which step a
// mesh arrives at never depends on GPU timing (deterministic runs). generateNow() waits for one node.
#include "engine/generation/gpu_payload_generator.h"
#include "engine/vk/device.h"
#include "engine/vk/vk_handles.h"
#include "planet/physics/collision_mesh.h"

#include <deque>
#include <vector>

namespace globe {

class GpuCollisionMeshSource final : public CollisionMeshSource {
 public:
  // `device` and `model` must outlive the source. `maxInFlight` asynchronous slots (one more is
  // kept for generateNow); `latencySteps` as above.
  GpuCollisionMeshSource(vk::Device& device, const ElevationModel& model, uint32_t cells, uint32_t maxInFlight,
                         uint32_t latencySteps = 0);
  ~GpuCollisionMeshSource() override;

  uint32_t cells() const override { return generator_.cells(); }
  void generate(std::span<const NodeId> nodes) override;
  void collect(std::vector<CollisionMesh>& finished) override;
  CollisionMesh generateNow(const NodeId& node) override;
  uint32_t inFlight() const override { return uint32_t(jobs_.size()); }
  void finishAll() override;
  // Device time of every generation so far (ms), and nodes generated.
  double gpuTime_ms() const { return generator_.gpuTime_ms(); }
  uint64_t nodesGenerated() const { return generator_.nodesGenerated(); }

 private:
  struct Job {
    NodeId node;
    uint32_t slot = 0;
    uint64_t collectBy = 0;  // the collect() call that must hand it out
    bool done = false;
  };
  // Collects finished generations into jobs_ (done flags); non-blocking.
  void poll();
  // The mesh from the slot's position block, which its batch copied into readback_.
  CollisionMesh meshFromReadback(const NodeId& node, uint32_t slot) const;

  vk::Device& device_;
  GpuPayloadGenerator generator_;
  uint32_t syncSlot_;
  uint32_t latencySteps_;
  vk::Buffer readback_;
  std::vector<uint32_t> freeSlots_;
  std::deque<Job> jobs_;
  std::vector<GenerationResult> results_;
  uint64_t collects_ = 0;
};

}  // namespace globe
