#pragma once
// The collision-mesh pool [Frasson 2018, §3.4]: collision meshes have their own pool, apart from the
// render payloads, with a memory budget in MiB and eviction by distance to the objects. Requests
// come in two of the shared RequestPriority classes (planet/lod/node_residency.h):
//   kContact   a node a body will touch within the look-ahead: generated synchronously, now;
//   kCollision a node within an object's radius of interest: queued, started under a per-step
//              budget and a cap on generations in flight, nearest first, collected on a later step.
// A node a body touched at this or the previous step is pinned: never evicted, whatever the budget.
// Eviction takes nodes no object asked for this step first, then the farthest from every object.
//
// Per step:  beginStep(step)          collect finished meshes (the listener adds them to the world)
//            request / requireNow     from the collision selection and the predicted contacts
//            pin                      the nodes bodies touch
//            dispatch()               evict as needed, start asynchronous generations
#include "planet/core/error.h"
#include "planet/lod/node_residency.h"
#include "planet/physics/collision_mesh.h"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace globe {

struct CollisionPoolConfig {
  double budget_MiB = 256.0;     // resident meshes; > 0
  uint32_t dispatchBudget = 16;  // asynchronous generations started per step; >= 1
  uint32_t maxInFlight = 64;     // asynchronous generations in flight at once; >= 1
};

Status validateCollisionPoolConfig(const CollisionPoolConfig& config);

// Told when a mesh becomes resident and before it is dropped (the physics world's static bodies).
// The mesh passed to meshResident stays at the same address until meshEvicted for its node.
class CollisionMeshListener {
 public:
  virtual ~CollisionMeshListener() = default;
  virtual void meshResident(const CollisionMesh& mesh) = 0;
  virtual void meshEvicted(const NodeId& node) = 0;
};

struct CollisionPoolStats {
  uint64_t generatedSync = 0;   // predicted contacts that had to wait for their mesh
  uint64_t generatedAsync = 0;  // meshes that arrived through the queue
  uint64_t evicted = 0;
  uint64_t droppedLate = 0;  // asynchronous results for nodes already generated synchronously
  uint32_t resident = 0;
  uint32_t inFlight = 0;
  uint32_t queued = 0;  // requests of this step not started
  size_t residentBytes = 0;
  double residentMiB() const { return double(residentBytes) / (1024.0 * 1024.0); }
};

class CollisionMeshPool {
 public:
  // `source` and `listener` must outlive the pool. `config` must be valid.
  CollisionMeshPool(const CollisionPoolConfig& config, CollisionMeshSource& source, CollisionMeshListener& listener);
  ~CollisionMeshPool();
  CollisionMeshPool(const CollisionMeshPool&) = delete;
  CollisionMeshPool& operator=(const CollisionMeshPool&) = delete;

  // Starts step `step` (strictly increasing) and collects finished asynchronous meshes.
  void beginStep(uint64_t step);
  bool isResident(const NodeId& node) const;
  const CollisionMesh* mesh(const NodeId& node) const;
  // kContact: makes the node resident before returning (synchronous generation when missing).
  void requireNow(const NodeId& node, double distance_m);
  // kCollision: queues the node; distance_m to the nearest object. The requests of one step form a
  // round (one collision selection) that replaces the previous round's queue; nodes of the newest
  // round count as wanted until the next one.
  void request(const NodeId& node, double distance_m);
  // A body touches the node: it is not evicted at this step or the next.
  void pin(const NodeId& node);
  // Evicts as needed and starts at most dispatchBudget asynchronous generations, nearest first.
  void dispatch();
  // A loading phase (before the first step): starts every queued request and waits for them all,
  // so they are resident when it returns.
  void generateQueued();

  const CollisionPoolStats& stats() const { return stats_; }
  size_t budgetBytes() const { return budgetBytes_; }
  // Set once, the first time the budget was full of pinned or wanted nodes.
  const std::string& exhaustionWarning() const { return warning_; }

 private:
  enum class State : uint8_t { kInFlight, kResident };
  struct Entry {
    State state = State::kInFlight;
    CollisionMesh mesh;
    uint64_t lastRequestStep = 0;
    uint64_t lastPinStep = 0;
    bool pinnedEver = false;
    double distance_m = 0.0;
  };
  void collectFinished();
  void dispatchUpTo(uint32_t budget);
  void insertResident(CollisionMesh mesh);
  // Frees room for `bytes` more; false when only pinned or wanted nodes are left.
  bool makeRoom(size_t bytes);
  bool evictable(const Entry& e) const;
  void updateStats();

  CollisionPoolConfig config_;
  CollisionMeshSource& source_;
  CollisionMeshListener& listener_;
  size_t budgetBytes_ = 0;
  size_t meshBytes_ = 0;
  uint64_t step_ = 0;
  uint64_t roundStep_ = 0;  // step of the newest round of requests
  size_t nextPending_ = 0;  // first request of the round not yet looked at by dispatch()
  std::unordered_map<uint64_t, Entry> entries_;
  std::vector<std::pair<double, uint64_t>> pending_;  // (distance, key) of the newest round
  std::vector<CollisionMesh> finished_;
  std::vector<NodeId> jobs_;
  CollisionPoolStats stats_;
  std::string warning_;
};

}  // namespace globe
