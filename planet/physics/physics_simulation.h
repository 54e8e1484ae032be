#pragma once
// One physics step over the whole chain [Frasson 2018, §3.4]:
//
//   CollisionMeshPool::beginStep   collect asynchronous meshes (they become static Bullet bodies)
//   CollisionSelectionWorker       newest round of nodes within each object's radius of interest
//    └─ pool.request (kCollision)  queued, nearest first
//   predicted contacts             per awake body: will its swept bounding sphere reach the surface
//    └─ pool.requireNow (kContact) within the look-ahead? Missing nodes under it are generated now
//   CollisionMeshPool::dispatch    start asynchronous generations under the per-step budget
//   PhysicsWorld::step             gravity along the vertical, Bullet, contacts
//   pool.pin                       the nodes bodies touch are never evicted
//   worker.submit                  the bodies' new positions, selected while the next step runs
#include "planet/model/elevation_model.h"
#include "planet/physics/collision_mesh_pool.h"
#include "planet/physics/collision_selection_worker.h"
#include "planet/physics/physics_world.h"

#include <memory>
#include <vector>

namespace globe {

struct SimulationSettings {
  int level = 14;                 // collision node level L
  double interestRadius_m = 8.0;  // radius of interest R around each body (added to its size)
  PhysicsSettings physics;        // planetRadius_m and surfaceGravity_m_s2 come from the model
  CollisionPoolConfig pool;
};

Status validateSimulationSettings(const SimulationSettings& settings);

struct SimulationStats {
  uint64_t steps = 0;
  std::vector<double> step_ms;     // each whole step (everything above, synchronous generation included)
  std::vector<double> physics_ms;  // PhysicsWorld::step alone
  // The same in CPU time of the stepping thread (CLOCK_THREAD_CPUTIME_ID): what a step costs when
  // the machine is shared and wall time includes waiting for a core.
  std::vector<double> stepCpu_ms;
  std::vector<double> physicsCpu_ms;
  uint64_t predictedContacts = 0;  // body-steps with a predicted contact
  uint64_t predictedMissing = 0;   // of those, nodes that were not resident (each generated synchronously)
  uint64_t selectionRounds = 0;
  double selection_ms = 0.0;  // worker time, all rounds
};

class PhysicsSimulation {
 public:
  // `model` and `source` must outlive the simulation; `settings` must be valid.
  PhysicsSimulation(const ElevationModel& model, CollisionMeshSource& source, const SimulationSettings& settings);
  ~PhysicsSimulation();

  uint32_t addBody(const BodySpec& spec);
  void step();
  // Waits for the selection worker's pending round and applies it (tests: a deterministic start).
  void settleSelection();
  // A loading phase before the first step: applies the bodies' first selection round and makes
  // every node it asks for resident, waiting for the generations, so that no step starts with the
  // whole neighbourhood missing (then the first steps generate synchronously whatever the bodies
  // are about to touch, ~200 meshes for 1 000 bodies dropped 1-100 m).
  void prepare();

  const PhysicsWorld& world() const { return *world_; }
  const CollisionMeshPool& pool() const { return *pool_; }
  const SimulationStats& stats() const { return stats_; }
  const SimulationSettings& settings() const { return settings_; }
  // Highest the surface can be within `arc_m` of the direction of `position_m`, from the resident
  // mesh of the node below when there is one, else the exact elevation plus a slope bound.
  double surfaceMaxRadius(const glm::dvec3& position_m, double arc_m) const;

 private:
  // Around a body's swept sphere: a larger sphere whose every node was resident when it was made,
  // and the highest those meshes reach. While the body's later swept spheres stay inside it and no
  // mesh was evicted, no node can be missing and the predicted-contact test is one comparison.
  struct ContactCover {
    glm::dvec3 centre_m{0.0};
    double radius_m = -1.0;     // < 0: none
    uint64_t evictions = 0;     // the pool's eviction count when it was made
    uint64_t retryStep = 0;     // a node was missing: no new attempt before this step
    double surfaceMax_m = 0.0;  // highest vertex radius of its meshes, metres from the planet centre
  };
  bool covered(const ContactCover& cover, const CollisionQuery& swept) const;
  void makeCover(ContactCover& cover, const CollisionQuery& swept, double speed_m_s,
                 std::vector<SelectedCollisionNode>& scratch) const;
  void applyRound(const CollisionSelectionRound& round);
  void predictContacts();
  void submitSelection();

  const ElevationModel& model_;
  SimulationSettings settings_;
  double minSurfaceRadius_m_;
  double slopeBound_;
  std::unique_ptr<PhysicsWorld> world_;
  std::unique_ptr<CollisionMeshPool> pool_;
  std::unique_ptr<CollisionSelectionWorker> worker_;
  // Steps between submitting a selection round and applying it.
  static constexpr uint64_t kRoundSteps = 4;
  uint64_t pendingRound_ = 0;
  uint64_t roundSubmitStep_ = 0;
  CollisionSelectionRound round_;
  struct ContactPrediction {
    bool contact = false;
    std::vector<SelectedCollisionNode> missing;  // nodes under the swept sphere not resident
  };
  std::vector<ContactPrediction> predictions_;  // per body, this step
  std::vector<ContactCover> covers_;            // per body
  SimulationStats stats_;
};

}  // namespace globe
