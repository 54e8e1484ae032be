#pragma once
// The collision selection on its own thread [Frasson 2018, §3.4]: the simulation hands it the
// objects' positions after a step and picks up the nodes they need one or more steps later, so
// descending 30 quadtrees for every object never lengthens a physics step. One round at a time:
// submit() while a round runs replaces the waiting input (only the newest positions matter).
// The lock guards only the input and the output hand-over; the selection itself runs unlocked on
// the worker's own copies. An object's selection is made with its query radius plus `reuse_m` and
// reused by later rounds while its query stays inside that larger cap, so an object at rest (or
// moving slowly) costs nothing; the round is then a superset of the exact one, never less.
#include "planet/geometry/face_mapping.h"
#include "planet/physics/collision_selection.h"

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace globe {

struct ObjectQuery {
  uint32_t object = 0;  // stable id (dense from 0): its last selection may be reused
  CollisionQuery query;
  double reuse_m = 0.0;  // >= 0: how far the object may go before it is selected again
};

struct CollisionSelectionRound {
  uint64_t round = 0;                        // submit() count this answers
  std::vector<SelectedCollisionNode> nodes;  // deduplicated, nearest distance per node, sorted nearest first
  double select_ms = 0.0;                    // worker time of the round
};

class CollisionSelectionWorker {
 public:
  // `mapping` must outlive the worker.
  CollisionSelectionWorker(const FaceMapping& mapping, double minSurfaceRadius_m, int level);
  ~CollisionSelectionWorker();
  CollisionSelectionWorker(const CollisionSelectionWorker&) = delete;
  CollisionSelectionWorker& operator=(const CollisionSelectionWorker&) = delete;

  // Queues a round for these queries; returns its number.
  uint64_t submit(std::vector<ObjectQuery> queries);
  // Moves the newest finished round into `out`; false when none finished since the last take.
  bool take(CollisionSelectionRound& out);
  // Blocks until the round `round` (or a later one) has finished (tests, warm-up).
  void waitFor(uint64_t round);

 private:
  // An object's last selection: the nodes within radius_m of position_m (its query's radius plus
  // the reuse room). Read and written by the worker thread only.
  struct Selection {
    glm::dvec3 position_m{0.0};
    double radius_m = -1.0;  // < 0: none
    std::vector<SelectedCollisionNode> nodes;
  };
  void run();
  CollisionSelectionRound selectRound(const std::vector<ObjectQuery>& queries, uint64_t round);
  // The object's nodes for `q`, reused or selected again; distances to q's position.
  void selectObject(const ObjectQuery& q, std::vector<SelectedCollisionNode>& out);

  const FaceMapping& mapping_;
  double minSurfaceRadius_m_;
  int level_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  std::vector<ObjectQuery> input_;
  std::vector<Selection> selections_;  // per object
  uint64_t submitted_ = 0;
  uint64_t finished_ = 0;
  bool haveInput_ = false;
  bool haveOutput_ = false;
  bool stop_ = false;
  CollisionSelectionRound output_;
  std::thread thread_;  // last: starts after every member it reads
};

}  // namespace globe
