#pragma once
// The node/payload pool [Frasson 2018, §3.5.2]: fixed-capacity tables of nodes and payload slots
// sized from a RAM and a VRAM budget, a prioritised request queue drained under a per-frame dispatch
// budget with a cap on generations in flight, and eviction by distance and level (least recently
// used among equals). It is the selection's NodeResidency: a node is drawable only once its payload
// is resident, and nothing is generated unless the selection (or a query) asked for it.
//
// Invariants the tests check:
//  - the resident set is closed under parents (a node is evicted only when none of its children is
//    resident or being generated), and the 30 roots are never evicted: selection always has
//    something to draw, never a hole;
//  - a slot used by a frame that the GPU may still be reading (frame > completedFrame) is never
//    handed to a generation job;
//  - after warm-up nothing allocates: tables, queue and scratch vectors have fixed capacity.
//
// Prefetch (RequestPriority::kPrefetch, docs/streaming.md) is strictly lower than what the view
// waits for: it sorts last, only uses dispatch budget the view left over, starts only while at most
// maxInFlight - dispatchBudget generations are in flight (one frame's budget stays free for the
// next frame's visible requests), never marks nodes as wanted (isResidentForPrefetch), only takes
// free slots or evicts a node farther away in its own widths than the prefetched one (no churn), and
// never warns about exhaustion.
//
// Per frame:   beginFrame(frame, camera, completedFrame)   collect finished generations
//              selector.select(camera, pool, selection)    isResident / request
//              markUsed(selection)                          pins the frame's slots
//              dispatch()                                   evict as needed, start generations
#include "planet/geometry/face_mapping.h"
#include "planet/lod/node_residency.h"
#include "planet/lod/selection.h"
#include "planet/streaming/frame_budget.h"
#include "planet/streaming/payload_generator.h"
#include "planet/streaming/streaming_stats.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace globe {

struct StreamingConfig {
  double ramBudget_MiB = 64.0;    // node table (structure, bounds data, links); > 0
  double vramBudget_MiB = 512.0;  // payload slots; > 0
  uint32_t dispatchBudget = 8;    // generations started per frame (source: 8); >= 1
  uint32_t maxInFlight = 32;      // generations in flight at once (source: 32); >= 1
  uint32_t maxSlots = 0;          // optional cap on payload slots below the VRAM budget (0 = none)
  // How errors (field) and the exhaustion warning (words) name the VRAM budget: a second pool with a
  // budget of its own (the imagery tiles') names that one.
  std::string vramBudgetField = "vram_budget_mib";
  std::string vramBudgetName = "the VRAM budget";
  FrameBudget budget;  // per-frame nodes, triangles and requests (frame_budget.h)
};

// Validates a config; errors name the field.
Status validateStreamingConfig(const StreamingConfig& config);

class PayloadPool final : public NodeResidency {
 public:
  // `generator` and `mapping` must outlive the pool. `radius_m` is the planet radius (for distances).
  // Errors: invalid config, or budgets too small for the 30 roots plus a working set.
  static Result<std::unique_ptr<PayloadPool>> create(const StreamingConfig& config, PayloadGenerator& generator,
                                                     double radius_m,
                                                     const FaceMapping& mapping = RhombusFaceMapping::get());

  // NodeResidency (called by the selection). isResident also notes that the current frame wants
  // the node: a node the selection is waiting to refine into is not evicted for another request.
  bool isResident(const NodeId& node) const override;
  bool isResidentForPrefetch(const NodeId& node) const override;
  void request(const NodeId& node, RequestPriority priority, double distance_m) override;
  std::optional<RadiusRange> knownRadiusRange(const NodeId& node) const override;
  std::optional<double> knownGeometricError(const NodeId& node) const override;

  // Asks (kRoot) for every root not resident yet: the warm-up's whole planet.
  void requestRoots(double distance_m);
  // Starts frame `frame` (strictly increasing). `completedFrame`: every frame <= it has finished on
  // the GPU, so slots only those frames used may be rewritten.
  void beginFrame(uint64_t frame, const glm::dvec3& camera_m, uint64_t completedFrame);
  // Marks the slots this frame draws as in use until the frame completes.
  void markUsed(std::span<const SelectedNode> nodes);
  // Drains the queue: evicts as needed, starts at most dispatchBudget generations.
  void dispatch();

  // Slot holding the node's payload, or nullopt when it is not resident.
  std::optional<uint32_t> slotOf(const NodeId& node) const;
  const StreamingStats& stats() const { return stats_; }
  uint32_t slotCapacity() const { return slotCapacity_; }
  uint32_t nodeCapacity() const { return nodeCapacity_; }
  // Frames from the first visible (kVisible/kRoot) request to resident, over the pool's life:
  // latencyHistogram()[k] counts k frames (the last bucket collects everything longer). A node
  // prefetched before the view asked for it is not counted (its wait was 0 frames from the view's
  // side: it was never drawn coarser); see prefetchHits().
  std::span<const uint64_t> latencyHistogram() const { return latency_; }
  // Completed generations nobody but the prefetch had asked for when they finished, over the pool's
  // life; and how many of those the view later asked for (isResident) while still resident.
  uint64_t prefetchCompleted() const { return prefetchCompleted_; }
  uint64_t prefetchHits() const { return prefetchHits_; }
  // Frames at or below which `fraction` (0..1] of completed requests became resident.
  uint32_t latencyPercentile(double fraction) const;
  // Set once, when the pool first had to skip a request because no slot could be freed.
  const std::string& exhaustionWarning() const { return exhaustionWarning_; }
  // One line per kind of trouble, in the order they first happened (pool exhausted, node table
  // full, generation failed): each is a degradation to coarser terrain the user should hear of once.
  std::span<const std::string> warnings() const { return warnings_; }
  // Generations that failed (GenerationResult::failed), over the pool's life and since the last
  // one that succeeded.
  uint64_t failedGenerations() const { return failedTotal_; }
  uint32_t consecutiveFailures() const { return consecutiveFailures_; }

 private:
  PayloadPool(const StreamingConfig& config, PayloadGenerator& generator, double radius_m, const FaceMapping& mapping,
              uint32_t slotCapacity, uint32_t nodeCapacity);

  enum class State : uint8_t { kFree, kQueued, kInFlight, kResident };
  struct NodeRecord {
    uint64_t key = kEmptyKey;
    State state = State::kFree;
    uint8_t level = 0;
    uint16_t activeChildren = 0;  // children queued-for-generation, in flight or resident
    uint32_t slot = kNoSlot;
    uint64_t firstRequestFrame = 0;         // first visible (non-prefetch) request
    bool visibleRequested = false;          // a kVisible/kRoot request arrived before resident
    mutable bool prefetchedUnused = false;  // resident from prefetch alone, not yet asked for by the view
    uint64_t lastUsedFrame = 0;             // last frame that drew this node's slot
    mutable uint64_t lastWantedFrame = 0;   // last frame the selection asked whether it is resident
    uint64_t lastRequestFrame = 0;
    RequestPriority priority = RequestPriority::kVisible;
    double distance_m = 0.0;
    glm::dvec3 centre_m{0.0};  // node centre on the reference sphere, metres
    RadiusRange radius;
    double geometricError_m = 0.0;
  };
  static constexpr uint64_t kEmptyKey = ~uint64_t{0};
  static constexpr uint64_t kTombstone = ~uint64_t{0} - 1;
  static constexpr uint32_t kNoSlot = ~uint32_t{0};

  // Open-addressing hash table over node keys (linear probing, fixed capacity: no allocation).
  int64_t find(uint64_t key) const;
  int64_t insert(const NodeId& node);
  void erase(int64_t index);
  void adjustParentCount(const NodeId& node, int delta);
  // Fills candidates_ with the evictable resident nodes and sorts the worst `count` first.
  void gatherCandidates(size_t count);
  // Evicts candidates_[index] (gathered this dispatch; still a valid victim).
  void evictCandidate(size_t index);
  // dispatch()'s steps: drop requests not repeated this frame and sort the rest (priority, then
  // distance); evict for the `want` first requests, returning the index of the next unused victim;
  // start generations, returning how many pending requests were taken; refresh the stats.
  void dropUnrequestedAndSort();
  size_t evictForUrgent(uint32_t want);
  size_t startJobs(size_t nextVictim);
  void updateDispatchStats();
  // floor(2 log2(distance / node width)): larger buckets are evicted first.
  int distanceBucket(const NodeRecord& r) const;
  enum class PoolWarning : uint8_t { kSlotsExhausted, kNodeTableFull, kGenerationFailed, kCount };
  void warnOnce(PoolWarning kind, const std::function<std::string()>& message);
  // A failed job's node: its slot is freed and the node forgotten (requested again by the view).
  void forgetFailed(int64_t index);
  void rehash();
  void releaseSlot(uint32_t slot, uint64_t lastUsedFrame);

  StreamingConfig config_;
  PayloadGenerator& generator_;
  const FaceMapping& mapping_;
  double radius_m_;
  uint32_t slotCapacity_ = 0;
  uint32_t nodeCapacity_ = 0;
  std::vector<NodeRecord> table_;  // power-of-two size >= 2 * nodeCapacity_
  uint32_t liveNodes_ = 0;
  uint32_t tombstones_ = 0;
  std::vector<uint32_t> freeSlots_;
  std::vector<uint64_t> slotOwner_;  // node key filling or holding each slot, kEmptyKey if none
  struct EvictionCandidate {
    int bucket;         // floor(2 log2(distance / node width)): larger is evicted first
    uint64_t lastUsed;  // older is evicted first among equal buckets
    uint64_t key;
  };
  std::vector<EvictionCandidate> candidates_;  // scratch for dispatch()
  // Slots released while a frame in flight may still read them: (slot, last use).
  std::vector<std::pair<uint32_t, uint64_t>> retiredSlots_;
  std::vector<NodeRecord> scratchTable_;  // rehash target, same size as table_
  std::vector<int64_t> pending_;          // table indices requested this frame (deduplicated)
  std::vector<GenerationJob> jobs_;
  std::vector<GenerationResult> finished_;
  std::vector<uint64_t> latency_;
  uint64_t frame_ = 0;
  uint64_t completedFrame_ = 0;
  uint32_t inFlight_ = 0;
  mutable uint64_t prefetchHits_ = 0;
  uint64_t prefetchCompleted_ = 0;
  glm::dvec3 camera_m_{0.0};
  StreamingStats stats_;
  std::string exhaustionWarning_;
  std::vector<std::string> warnings_;
  std::array<bool, size_t(PoolWarning::kCount)> warned_{};
  uint64_t failedTotal_ = 0;
  uint32_t consecutiveFailures_ = 0;
};

}  // namespace globe
