#include "planet/streaming/payload_pool.h"

#include "planet/geometry/triacontahedron.h"

#include "planet/core/hash.h"
#include "planet/lod/lod_ranges.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>

namespace globe {

namespace {
constexpr double kMiB = 1024.0 * 1024.0;
constexpr size_t kLatencyBuckets = 64;
}  // namespace

Status validateStreamingConfig(const StreamingConfig& c) {
  if (!(c.ramBudget_MiB > 0) || !std::isfinite(c.ramBudget_MiB))
    return Error::inField("ram_budget_mib", "must be a finite number > 0");
  if (!(c.vramBudget_MiB > 0) || !std::isfinite(c.vramBudget_MiB))
    return Error::inField(c.vramBudgetField, "must be a finite number > 0");
  if (c.dispatchBudget < 1) return Error::inField("dispatch_budget", "must be >= 1");
  if (c.maxInFlight < 1) return Error::inField("max_in_flight", "must be >= 1");
  return Ok{};
}

Result<std::unique_ptr<PayloadPool>> PayloadPool::create(const StreamingConfig& config, PayloadGenerator& generator,
                                                         double radius_m, const FaceMapping& mapping) {
  if (auto s = validateStreamingConfig(config); !s) return s.error();
  if (!(radius_m > 0) || !std::isfinite(radius_m)) return Error::inField("radius_m", "must be a finite number > 0");
  size_t slotBytes = std::max<size_t>(generator.slotBytes(), 1);
  double slots = std::floor(config.vramBudget_MiB * kMiB / double(slotBytes));
  if (config.maxSlots > 0) slots = std::min(slots, double(config.maxSlots));
  // The 30 roots are pinned; below that plus one refinement of each there is no working set.
  if (slots < 30 + 4)
    return Error::inField(config.vramBudgetField, "too small: " + std::to_string(int64_t(slots)) +
                                                      " payload slots of " + std::to_string(slotBytes) +
                                                      " bytes fit, at least 34 are needed");
  // The hash table is twice the node capacity (load <= 0.5) and counts against the RAM budget.
  double nodes = std::floor(config.ramBudget_MiB * kMiB / (2.0 * sizeof(NodeRecord)));
  if (nodes < slots + 256)
    return Error::inField("ram_budget_mib", "too small for the VRAM budget: " + std::to_string(int64_t(nodes)) +
                                                " nodes fit, " + std::to_string(int64_t(slots) + 256) + " are needed");
  nodes = std::min(nodes, 1.0 * (1u << 30));
  return std::unique_ptr<PayloadPool>(
      new PayloadPool(config, generator, radius_m, mapping, uint32_t(slots), uint32_t(nodes)));
}

PayloadPool::PayloadPool(const StreamingConfig& config, PayloadGenerator& generator, double radius_m,
                         const FaceMapping& mapping, uint32_t slotCapacity, uint32_t nodeCapacity)
    : config_(config),
      generator_(generator),
      mapping_(mapping),
      radius_m_(radius_m),
      slotCapacity_(slotCapacity),
      nodeCapacity_(nodeCapacity) {
  size_t tableSize = std::bit_ceil(size_t(nodeCapacity_) * 2);
  table_.resize(tableSize);
  scratchTable_.resize(tableSize);
  freeSlots_.reserve(slotCapacity_);
  for (uint32_t s = slotCapacity_; s-- > 0;) freeSlots_.push_back(s);
  retiredSlots_.reserve(slotCapacity_);
  slotOwner_.assign(slotCapacity_, kEmptyKey);
  candidates_.reserve(slotCapacity_);
  pending_.reserve(nodeCapacity_);
  jobs_.reserve(config_.dispatchBudget);
  finished_.reserve(config_.maxInFlight * 2u);
  latency_.assign(kLatencyBuckets, 0);
}

int64_t PayloadPool::find(uint64_t key) const {
  size_t mask = table_.size() - 1;
  for (size_t i = mix64(key) & mask, probes = 0; probes < table_.size(); i = (i + 1) & mask, ++probes) {
    if (table_[i].key == key) return int64_t(i);
    if (table_[i].key == kEmptyKey) return -1;
  }
  return -1;
}

int64_t PayloadPool::insert(const NodeId& node) {
  if (liveNodes_ >= nodeCapacity_) return -1;
  if (tombstones_ > table_.size() / 4) rehash();
  size_t mask = table_.size() - 1;
  uint64_t key = node.key();
  for (size_t i = mix64(key) & mask;; i = (i + 1) & mask) {
    if (table_[i].key == kEmptyKey || table_[i].key == kTombstone) {
      if (table_[i].key == kTombstone) --tombstones_;
      NodeRecord& r = table_[i];
      r = NodeRecord{};
      r.key = key;
      r.level = node.level;
      r.centre_m = nodeCentreDirection(mapping_, node) * radius_m_;
      ++liveNodes_;
      return int64_t(i);
    }
  }
}

void PayloadPool::erase(int64_t index) {
  NodeRecord& r = table_[size_t(index)];
  adjustParentCount(NodeId::fromKey(r.key), -1);
  r.key = kTombstone;
  r.state = State::kFree;
  --liveNodes_;
  ++tombstones_;
}

void PayloadPool::rehash() {
  // Re-inserts live records into the scratch table, then swaps: no allocation. Indices change, so
  // the pending list is rebuilt from the queued records.
  for (auto& r : scratchTable_) r = NodeRecord{};
  size_t mask = scratchTable_.size() - 1;
  for (const NodeRecord& r : table_) {
    if (r.key == kEmptyKey || r.key == kTombstone) continue;
    size_t i = mix64(r.key) & mask;
    while (scratchTable_[i].key != kEmptyKey) i = (i + 1) & mask;
    scratchTable_[i] = r;
  }
  table_.swap(scratchTable_);
  tombstones_ = 0;
  pending_.clear();
  for (size_t i = 0; i < table_.size(); ++i)
    if (table_[i].key != kEmptyKey && table_[i].state == State::kQueued) pending_.push_back(int64_t(i));
}

void PayloadPool::adjustParentCount(const NodeId& node, int delta) {
  if (node.level == 0) return;
  int64_t p = find(node.parent().key());
  if (p < 0) return;
  auto& count = table_[size_t(p)].activeChildren;
  assert(delta > 0 || count > 0);
  count = uint16_t(int(count) + delta);
}

bool PayloadPool::isResident(const NodeId& node) const {
  int64_t i = find(node.key());
  if (i < 0) return false;
  const NodeRecord& r = table_[size_t(i)];
  r.lastWantedFrame = frame_;
  if (r.state != State::kResident) return false;
  if (r.prefetchedUnused) {
    r.prefetchedUnused = false;
    ++prefetchHits_;
  }
  return true;
}

bool PayloadPool::isResidentForPrefetch(const NodeId& node) const {
  int64_t i = find(node.key());
  return i >= 0 && table_[size_t(i)].state == State::kResident;
}

std::optional<uint32_t> PayloadPool::slotOf(const NodeId& node) const {
  int64_t i = find(node.key());
  if (i < 0 || table_[size_t(i)].state != State::kResident) return std::nullopt;
  return table_[size_t(i)].slot;
}

std::optional<RadiusRange> PayloadPool::knownRadiusRange(const NodeId& node) const {
  int64_t i = find(node.key());
  if (i < 0 || table_[size_t(i)].state != State::kResident) return std::nullopt;
  return table_[size_t(i)].radius;
}

std::optional<double> PayloadPool::knownGeometricError(const NodeId& node) const {
  int64_t i = find(node.key());
  if (i < 0 || table_[size_t(i)].state != State::kResident) return std::nullopt;
  return table_[size_t(i)].geometricError_m;
}

void PayloadPool::requestRoots(double distance_m) {
  for (int face = 0; face < kFaceCount; ++face) {
    const NodeId root{uint8_t(face), 0, 0, 0};
    if (!isResident(root)) request(root, RequestPriority::kRoot, distance_m);
  }
}

void PayloadPool::request(const NodeId& node, RequestPriority priority, double distance_m) {
  const bool prefetch = priority == RequestPriority::kPrefetch;
  int64_t i = find(node.key());
  if (i < 0) {
    i = insert(node);
    if (i < 0) {
      if (prefetch) return;  // look-ahead is optional: no warning, no stat
      ++stats_.starvedByPool;
      warnOnce(PoolWarning::kNodeTableFull, [&] {
        return "node pool full (" + std::to_string(nodeCapacity_) +
               " nodes): drawing coarser terrain; raise the RAM budget";
      });
      return;
    }
    NodeRecord& r = table_[size_t(i)];
    r.state = State::kQueued;
    adjustParentCount(node, +1);
    pending_.push_back(i);
  }
  NodeRecord& r = table_[size_t(i)];
  if (r.state == State::kResident) return;
  if (!prefetch && !r.visibleRequested) {
    // Latency is what the view waits: from its first request, even when a prefetch came earlier.
    r.visibleRequested = true;
    r.firstRequestFrame = frame_;
  }
  if (r.state != State::kQueued) return;  // already in flight
  if (r.lastRequestFrame != frame_) {
    r.lastRequestFrame = frame_;
    r.priority = priority;
    r.distance_m = distance_m;
    ++stats_.requested;
    if (prefetch) ++stats_.prefetchRequested;
  } else {
    if (r.priority == RequestPriority::kPrefetch && !prefetch) --stats_.prefetchRequested;
    r.priority = std::min(r.priority, priority);
    r.distance_m = std::min(r.distance_m, distance_m);
  }
}

void PayloadPool::releaseSlot(uint32_t slot, uint64_t lastUsedFrame) {
  slotOwner_[slot] = kEmptyKey;
  if (lastUsedFrame <= completedFrame_)
    freeSlots_.push_back(slot);
  else
    retiredSlots_.emplace_back(slot, lastUsedFrame);
}

void PayloadPool::beginFrame(uint64_t frame, const glm::dvec3& camera_m, uint64_t completedFrame) {
  assert(frame > frame_ || frame_ == 0);
  frame_ = frame;
  completedFrame_ = completedFrame;
  camera_m_ = camera_m;
  stats_ = StreamingStats{};

  // Slots released while a frame in flight still read them become free once those frames are done.
  for (size_t k = 0; k < retiredSlots_.size();) {
    if (retiredSlots_[k].second <= completedFrame_) {
      freeSlots_.push_back(retiredSlots_[k].first);
      retiredSlots_[k] = retiredSlots_.back();
      retiredSlots_.pop_back();
    } else {
      ++k;
    }
  }

  finished_.clear();
  generator_.collect(finished_);
  for (const GenerationResult& done : finished_) {
    --inFlight_;
    int64_t i = find(done.node.key());
    if (i < 0 || table_[size_t(i)].state != State::kInFlight || table_[size_t(i)].slot != done.slot) {
      // Not the job this pool started (never expected): the generator is done with the slot, nobody draws it.
      freeSlots_.push_back(done.slot);
      slotOwner_[done.slot] = kEmptyKey;
      if (i >= 0 && table_[size_t(i)].state == State::kInFlight && table_[size_t(i)].slot == done.slot) erase(i);
      continue;
    }
    if (done.failed) {
      forgetFailed(i);
      continue;
    }
    consecutiveFailures_ = 0;
    NodeRecord& r = table_[size_t(i)];
    r.state = State::kResident;
    r.radius = done.radius;
    r.geometricError_m = done.geometricError_m;
    r.lastUsedFrame = 0;
    if (r.visibleRequested) {
      uint64_t frames = frame_ - r.firstRequestFrame;
      ++latency_[std::min<size_t>(frames, kLatencyBuckets - 1)];
    } else {
      r.prefetchedUnused = true;
      ++prefetchCompleted_;
    }
    ++stats_.completed;
  }
}

void PayloadPool::forgetFailed(int64_t index) {
  // Nothing usable was written: the slot is free at once (no frame drew it), and the node is
  // forgotten, so the selection draws its parent and requests it again (a retry at the normal
  // budget, never a loop within the frame).
  NodeRecord& r = table_[size_t(index)];
  slotOwner_[r.slot] = kEmptyKey;
  freeSlots_.push_back(r.slot);
  erase(index);
  ++stats_.failed;
  ++failedTotal_;
  ++consecutiveFailures_;
  warnOnce(PoolWarning::kGenerationFailed, [&] {
    return "payload generation failed (" + generator_.lastFailure() + "): drawing coarser terrain meanwhile";
  });
}

void PayloadPool::markUsed(std::span<const SelectedNode> nodes) {
  for (const SelectedNode& n : nodes) {
    int64_t i = find(n.id.key());
    if (i >= 0 && table_[size_t(i)].state == State::kResident) table_[size_t(i)].lastUsedFrame = frame_;
    // A partial node is drawn from its own payload at half resolution: the same slot.
  }
}

int PayloadPool::distanceBucket(const NodeRecord& r) const {
  double ratio = glm::length(camera_m_ - r.centre_m) / nominalNodeWidth(r.level, radius_m_);
  return int(std::floor(2.0 * std::log2(std::max(ratio, 1e-6))));
}

void PayloadPool::gatherCandidates(size_t count) {
  // Victims: the resident nodes farthest from the camera in units of their own width (deep nodes go
  // before coarse ones at the same distance), least recently used among equals. Nodes the GPU may
  // still read, nodes with active children (the resident set stays closed under parents), nodes the
  // current frame draws or waits for, and the roots are kept. Distance, not view direction, decides:
  // what is just behind the camera survives. One pass over the slots, then a partial sort: O(slots)
  // per frame that evicts.
  candidates_.clear();
  for (uint32_t slot = 0; slot < slotCapacity_; ++slot) {
    if (slotOwner_[slot] == kEmptyKey) continue;
    int64_t i = find(slotOwner_[slot]);
    if (i < 0) continue;
    const NodeRecord& r = table_[size_t(i)];
    if (r.state != State::kResident || r.level == 0 || r.activeChildren > 0) continue;
    if (r.lastUsedFrame > completedFrame_ || r.lastUsedFrame == frame_ || r.lastWantedFrame == frame_) continue;
    candidates_.push_back({distanceBucket(r), r.lastUsedFrame, r.key});
  }
  auto worse = [](const EvictionCandidate& a, const EvictionCandidate& b) {
    if (a.bucket != b.bucket) return a.bucket > b.bucket;
    if (a.lastUsed != b.lastUsed) return a.lastUsed < b.lastUsed;
    return a.key < b.key;
  };
  size_t n = std::min(count, candidates_.size());
  std::partial_sort(candidates_.begin(), candidates_.begin() + std::ptrdiff_t(n), candidates_.end(), worse);
  candidates_.resize(n);
}

void PayloadPool::evictCandidate(size_t index) {
  // A parent whose last active child was evicted earlier in this dispatch was not a candidate when
  // gathered, so every candidate is still a leaf of the resident set.
  int64_t i = find(candidates_[index].key);
  NodeRecord& r = table_[size_t(i)];
  if (r.prefetchedUnused) r.prefetchedUnused = false;
  slotOwner_[r.slot] = kEmptyKey;
  freeSlots_.push_back(r.slot);
  erase(i);
  ++stats_.evicted;
}

void PayloadPool::dropUnrequestedAndSort() {
  // Requests not repeated this frame are no longer needed: nothing is generated that the current
  // view did not ask for.
  for (size_t k = 0; k < pending_.size();) {
    NodeRecord& r = table_[size_t(pending_[k])];
    if (r.state == State::kQueued && r.lastRequestFrame == frame_) {
      ++k;
      continue;
    }
    if (r.state == State::kQueued) erase(pending_[k]);
    pending_[k] = pending_.back();
    pending_.pop_back();
  }
  std::sort(pending_.begin(), pending_.end(), [&](int64_t a, int64_t b) {
    const NodeRecord& ra = table_[size_t(a)];
    const NodeRecord& rb = table_[size_t(b)];
    if (ra.priority != rb.priority) return ra.priority < rb.priority;
    if (ra.distance_m != rb.distance_m) return ra.distance_m < rb.distance_m;
    return ra.key < rb.key;  // deterministic order
  });
}

size_t PayloadPool::evictForUrgent(uint32_t want) {
  uint32_t urgent = 0;
  for (uint32_t k = 0; k < want; ++k)
    if (table_[size_t(pending_[k])].priority != RequestPriority::kPrefetch) ++urgent;
  size_t nextVictim = 0;
  if (want > freeSlots_.size()) {
    // One pass for this dispatch: the worst `want` victims, worst first. Urgent requests take them
    // unconditionally; prefetch only those farther (in node widths) than what it fetches.
    gatherCandidates(want - freeSlots_.size());
    uint32_t urgentNeed = urgent > freeSlots_.size() ? urgent - uint32_t(freeSlots_.size()) : 0;
    for (; nextVictim < std::min<size_t>(urgentNeed, candidates_.size()); ++nextVictim) evictCandidate(nextVictim);
  }
  return nextVictim;
}

size_t PayloadPool::startJobs(size_t nextVictim) {
  const uint32_t budget = config_.dispatchBudget;
  const uint32_t maxInFlight = config_.maxInFlight;
  // Prefetch leaves one frame's dispatch budget of in-flight room to the next frame's visible
  // requests (at least half of the cap stays usable by prefetch when the budget is that large).
  const uint32_t prefetchInFlightCap = std::max(maxInFlight / 2, maxInFlight - std::min(maxInFlight, budget));
  size_t taken = 0;
  for (; taken < pending_.size(); ++taken) {
    if (jobs_.size() >= budget || inFlight_ >= maxInFlight) break;
    NodeRecord& r = table_[size_t(pending_[taken])];
    if (r.priority == RequestPriority::kPrefetch) {
      // Sorted: everything from here on is prefetch.
      if (inFlight_ >= prefetchInFlightCap) break;
      if (freeSlots_.empty()) {
        if (nextVictim >= candidates_.size() || candidates_[nextVictim].bucket <= distanceBucket(r)) break;
        evictCandidate(nextVictim++);
      }
      ++stats_.prefetchDispatched;
    } else if (freeSlots_.empty()) {
      ++stats_.starvedByPool;
      warnOnce(PoolWarning::kSlotsExhausted, [&] {
        return "payload pool exhausted (" + std::to_string(slotCapacity_) + " slots): drawing coarser terrain; raise " +
               config_.vramBudgetName;
      });
      break;
    }
    r.slot = freeSlots_.back();
    freeSlots_.pop_back();
    slotOwner_[r.slot] = r.key;
    r.state = State::kInFlight;
    ++inFlight_;
    jobs_.push_back({NodeId::fromKey(r.key), r.slot});
  }
  return taken;
}

void PayloadPool::updateDispatchStats() {
  stats_.dispatched = uint32_t(jobs_.size());
  stats_.inFlight = inFlight_;
  stats_.queueLength = uint32_t(pending_.size());
  uint32_t used = slotCapacity_ - uint32_t(freeSlots_.size()) - uint32_t(retiredSlots_.size());
  stats_.residentNodes = used - inFlight_;
  stats_.residentMiB = double(used) * double(generator_.slotBytes()) / kMiB;
}

void PayloadPool::dispatch() {
  dropUnrequestedAndSort();
  jobs_.clear();
  const uint32_t maxInFlight = config_.maxInFlight;
  uint32_t room = std::min<uint32_t>(config_.dispatchBudget, maxInFlight - std::min(maxInFlight, inFlight_));
  uint32_t want = std::min<uint32_t>(room, uint32_t(pending_.size()));
  const size_t nextVictim = evictForUrgent(want);
  const size_t taken = startJobs(nextVictim);
  candidates_.clear();
  pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(taken));
  if (!jobs_.empty()) generator_.generate(jobs_);
  updateDispatchStats();
}

uint32_t PayloadPool::latencyPercentile(double fraction) const {
  uint64_t total = 0;
  for (uint64_t c : latency_) total += c;
  if (total == 0) return 0;
  uint64_t target = uint64_t(std::ceil(fraction * double(total)));
  uint64_t seen = 0;
  for (size_t k = 0; k < latency_.size(); ++k) {
    seen += latency_[k];
    if (seen >= target) return uint32_t(k);
  }
  return uint32_t(latency_.size() - 1);
}

void PayloadPool::warnOnce(PoolWarning kind, const std::function<std::string()>& message) {
  // The message is built only the first time: a starved or failing frame repeats every frame.
  if (warned_[size_t(kind)]) return;
  warned_[size_t(kind)] = true;
  warnings_.push_back(message());
  if (kind != PoolWarning::kGenerationFailed && exhaustionWarning_.empty()) exhaustionWarning_ = warnings_.back();
}

}  // namespace globe
