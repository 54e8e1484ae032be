#include "planet/physics/collision_mesh_pool.h"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace globe {

Status validateCollisionPoolConfig(const CollisionPoolConfig& config) {
  if (!(std::isfinite(config.budget_MiB) && config.budget_MiB > 0.0))
    return Error::inField("budget_MiB", "must be a positive number of MiB");
  if (config.dispatchBudget < 1) return Error::inField("dispatchBudget", "must be >= 1");
  if (config.maxInFlight < 1) return Error::inField("maxInFlight", "must be >= 1");
  return Ok{};
}

CollisionMeshPool::CollisionMeshPool(const CollisionPoolConfig& config, CollisionMeshSource& source,
                                     CollisionMeshListener& listener)
    : config_(config), source_(source), listener_(listener), budgetBytes_(size_t(config.budget_MiB * 1024.0 * 1024.0)) {
  assert(validateCollisionPoolConfig(config).ok());
}

CollisionMeshPool::~CollisionMeshPool() {
  for (auto& [key, entry] : entries_)
    if (entry.state == State::kResident) listener_.meshEvicted(NodeId::fromKey(key));
}

void CollisionMeshPool::beginStep(uint64_t step) {
  assert(step > step_ || step_ == 0);
  step_ = step;
  collectFinished();
}

void CollisionMeshPool::collectFinished() {
  finished_.clear();
  source_.collect(finished_);
  for (CollisionMesh& mesh : finished_) {
    auto it = entries_.find(mesh.node.key());
    if (it == entries_.end() || it->second.state == State::kResident) {
      ++stats_.droppedLate;  // generated synchronously meanwhile (or evicted while in flight)
      continue;
    }
    if (!makeRoom(mesh.bytes())) {
      entries_.erase(it);
      continue;
    }
    ++stats_.generatedAsync;
    insertResident(std::move(mesh));
  }
  updateStats();
}

bool CollisionMeshPool::isResident(const NodeId& node) const {
  auto it = entries_.find(node.key());
  return it != entries_.end() && it->second.state == State::kResident;
}

const CollisionMesh* CollisionMeshPool::mesh(const NodeId& node) const {
  auto it = entries_.find(node.key());
  return it != entries_.end() && it->second.state == State::kResident ? &it->second.mesh : nullptr;
}

void CollisionMeshPool::insertResident(CollisionMesh mesh) {
  Entry& e = entries_[mesh.node.key()];
  const bool wanted = e.lastRequestStep != 0;
  e.state = State::kResident;
  e.mesh = std::move(mesh);
  if (!wanted) e.lastRequestStep = step_;
  meshBytes_ += e.mesh.bytes();
  listener_.meshResident(e.mesh);
}

void CollisionMeshPool::requireNow(const NodeId& node, double distance_m) {
  auto it = entries_.find(node.key());
  if (it != entries_.end() && it->second.state == State::kResident) {
    it->second.distance_m = std::min(it->second.distance_m, distance_m);
    return;
  }
  CollisionMesh mesh = source_.generateNow(node);
  if (!makeRoom(mesh.bytes()) && warning_.empty())
    warning_ = fmt::format(
        "collision pool: {:.1f} MiB budget full of touched or wanted meshes; over budget for "
        "a predicted contact",
        config_.budget_MiB);
  ++stats_.generatedSync;
  Entry& e = entries_[node.key()];
  e.lastRequestStep = step_;
  e.distance_m = distance_m;
  insertResident(std::move(mesh));
  updateStats();
}

void CollisionMeshPool::request(const NodeId& node, double distance_m) {
  if (roundStep_ != step_) {
    roundStep_ = step_;
    pending_.clear();
    nextPending_ = 0;
  }
  auto it = entries_.find(node.key());
  if (it != entries_.end()) {
    it->second.lastRequestStep = step_;
    it->second.distance_m = distance_m;
    return;
  }
  pending_.emplace_back(distance_m, node.key());
}

void CollisionMeshPool::pin(const NodeId& node) {
  auto it = entries_.find(node.key());
  if (it == entries_.end()) return;
  it->second.lastPinStep = step_;
  it->second.pinnedEver = true;
}

bool CollisionMeshPool::evictable(const Entry& e) const {
  if (e.state != State::kResident) return false;
  if (e.pinnedEver && e.lastPinStep + 1 >= step_) return false;
  return true;
}

bool CollisionMeshPool::makeRoom(size_t bytes) {
  if (meshBytes_ + bytes <= budgetBytes_) return true;
  // Worst first: not in the newest round, then farthest from every object.
  std::vector<std::pair<std::pair<bool, double>, uint64_t>> victims;
  for (const auto& [key, e] : entries_)
    if (evictable(e)) victims.push_back({{e.lastRequestStep >= roundStep_, -e.distance_m}, key});
  std::sort(victims.begin(), victims.end());
  for (const auto& [order, key] : victims) {
    if (meshBytes_ + bytes <= budgetBytes_) break;
    if (order.first && warning_.empty())
      warning_ = fmt::format("collision pool: {:.1f} MiB budget too small for the meshes the objects want",
                             config_.budget_MiB);
    auto it = entries_.find(key);
    listener_.meshEvicted(it->second.mesh.node);
    meshBytes_ -= it->second.mesh.bytes();
    entries_.erase(it);
    ++stats_.evicted;
  }
  return meshBytes_ + bytes <= budgetBytes_;
}

void CollisionMeshPool::dispatch() { dispatchUpTo(config_.dispatchBudget); }

void CollisionMeshPool::generateQueued() {
  for (;;) {
    dispatchUpTo(config_.maxInFlight);
    if (source_.inFlight() == 0) return;  // nothing left to start (or no room for it)
    source_.finishAll();
    collectFinished();
  }
}

void CollisionMeshPool::dispatchUpTo(uint32_t budget) {
  if (nextPending_ == 0) std::stable_sort(pending_.begin(), pending_.end());
  jobs_.clear();
  const uint32_t room = config_.maxInFlight > source_.inFlight() ? config_.maxInFlight - source_.inFlight() : 0;
  const uint32_t want = std::min(budget, room);
  while (nextPending_ < pending_.size() && jobs_.size() < want) {
    const uint64_t key = pending_[nextPending_++].second;
    if (entries_.count(key)) continue;  // generated meanwhile
    if (meshBytes_ + collisionMeshBytes(source_.cells()) > budgetBytes_ &&
        !makeRoom(collisionMeshBytes(source_.cells())))
      break;  // keep it queued: room may free up when objects move on
    Entry& e = entries_[key];
    e.state = State::kInFlight;
    e.lastRequestStep = step_;
    e.distance_m = pending_[nextPending_ - 1].first;
    jobs_.push_back(NodeId::fromKey(key));
  }
  if (!jobs_.empty()) source_.generate(jobs_);
  updateStats();
}

void CollisionMeshPool::updateStats() {
  uint32_t resident = 0, inFlight = 0;
  for (const auto& [key, e] : entries_) (e.state == State::kResident ? resident : inFlight)++;
  stats_.resident = resident;
  stats_.inFlight = inFlight;
  stats_.queued = uint32_t(pending_.size() - nextPending_);
  stats_.residentBytes = meshBytes_;
}

}  // namespace globe
