#include "planet/physics/collision_selection_worker.h"

#include <algorithm>
#include <chrono>
#include <unordered_map>

namespace globe {

CollisionSelectionWorker::CollisionSelectionWorker(const FaceMapping& mapping, double minSurfaceRadius_m, int level)
    : mapping_(mapping), minSurfaceRadius_m_(minSurfaceRadius_m), level_(level), thread_([this] { run(); }) {}

CollisionSelectionWorker::~CollisionSelectionWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

uint64_t CollisionSelectionWorker::submit(std::vector<CollisionQuery> queries) {
  uint64_t round;
  {
    std::lock_guard lock(mutex_);
    input_ = std::move(queries);
    haveInput_ = true;
    round = ++submitted_;
  }
  wake_.notify_one();
  return round;
}

bool CollisionSelectionWorker::take(CollisionSelectionRound& out) {
  std::lock_guard lock(mutex_);
  if (!haveOutput_) return false;
  out = std::move(output_);
  haveOutput_ = false;
  return true;
}

void CollisionSelectionWorker::waitFor(uint64_t round) {
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return finished_ >= round; });
}

CollisionSelectionRound CollisionSelectionWorker::selectRound(const std::vector<CollisionQuery>& queries,
                                                              uint64_t round) const {
  const auto start = std::chrono::steady_clock::now();
  CollisionSelectionRound result;
  result.round = round;
  std::vector<SelectedCollisionNode> scratch;
  std::unordered_map<uint64_t, size_t> index;
  for (const CollisionQuery& query : queries) {
    scratch.clear();
    selectCollisionNodes(mapping_, minSurfaceRadius_m_, query, level_, scratch);
    for (const SelectedCollisionNode& s : scratch) {
      auto [it, inserted] = index.try_emplace(s.node.key(), result.nodes.size());
      if (inserted) {
        result.nodes.push_back(s);
      } else {
        result.nodes[it->second].distance_m = std::min(result.nodes[it->second].distance_m, s.distance_m);
      }
    }
  }
  std::stable_sort(
      result.nodes.begin(), result.nodes.end(),
      [](const SelectedCollisionNode& a, const SelectedCollisionNode& b) { return a.distance_m < b.distance_m; });
  result.select_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void CollisionSelectionWorker::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || haveInput_; });
    if (stop_) return;
    std::vector<CollisionQuery> queries = std::move(input_);
    const uint64_t round = submitted_;
    haveInput_ = false;
    lock.unlock();
    CollisionSelectionRound result = selectRound(queries, round);
    lock.lock();
    output_ = std::move(result);
    haveOutput_ = true;
    finished_ = round;
    done_.notify_all();
  }
}

}  // namespace globe
