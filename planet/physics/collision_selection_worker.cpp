#include "planet/physics/collision_selection_worker.h"

#include "planet/geometry/angles.h"

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

uint64_t CollisionSelectionWorker::submit(std::vector<ObjectQuery> queries) {
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

void CollisionSelectionWorker::selectObject(const ObjectQuery& q, std::vector<SelectedCollisionNode>& out) {
  if (q.object >= selections_.size()) selections_.resize(size_t(q.object) + 1);
  Selection& last = selections_[q.object];
  // Inside the last selection's cap (arcs on the lowest surface sphere, as selectCollisionNodes
  // measures them): every node within the query's radius is among its nodes.
  double moved_m =
      last.radius_m < 0.0 ? 0.0 : minSurfaceRadius_m_ * angleBetween_rad(last.position_m, q.query.position_m);
  if (last.radius_m < 0.0 || moved_m + q.query.radius_m > last.radius_m) {
    last.position_m = q.query.position_m;
    last.radius_m = q.query.radius_m + q.reuse_m;
    last.nodes.clear();
    selectCollisionNodes(mapping_, minSurfaceRadius_m_, {last.position_m, last.radius_m}, level_, last.nodes);
    moved_m = 0.0;
  }
  for (const SelectedCollisionNode& s : last.nodes) out.push_back({s.node, std::max(0.0, s.distance_m - moved_m)});
}

CollisionSelectionRound CollisionSelectionWorker::selectRound(const std::vector<ObjectQuery>& queries, uint64_t round) {
  const auto start = std::chrono::steady_clock::now();
  CollisionSelectionRound result;
  result.round = round;
  std::vector<SelectedCollisionNode> scratch;
  std::unordered_map<uint64_t, size_t> index;
  for (const ObjectQuery& query : queries) {
    scratch.clear();
    selectObject(query, scratch);
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
    std::vector<ObjectQuery> queries = std::move(input_);
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
