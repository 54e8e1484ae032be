#include "planet/physics/physics_simulation.h"

#include "planet/analysis/surface_ray.h"
#include "planet/geometry/angles.h"
#include "planet/geometry/face_mapping.h"
#include "planet/lod/lod_ranges.h"

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <ctime>

namespace globe {

namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double threadCpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Slack above the predicted-contact surface (metres): Bullet's contact margin and rounding.
constexpr double kContactSlack_m = 0.1;
// A contact cover's room beyond the swept sphere (metres, plus eight steps of travel), and the
// steps before a cover that found a node missing is tried again.
constexpr double kCoverPad_m = 0.5;
constexpr uint64_t kCoverRetrySteps = 4;
// Room a body's collision selection leaves for its motion (metres, plus three rounds of travel).
constexpr double kSelectionReuse_m = 1.0;

}  // namespace

Status validateSimulationSettings(const SimulationSettings& settings) {
  if (settings.level < 0 || settings.level > kMaxNodeLevel)
    return Error::inField("level", "must be within [0, " + std::to_string(kMaxNodeLevel) + "]");
  if (!(std::isfinite(settings.interestRadius_m) && settings.interestRadius_m >= 0.0 &&
        settings.interestRadius_m <= 1e6))
    return Error::inField("radius", "must be within [0, 1e6] m");
  if (!(std::isfinite(settings.physics.step_s) && settings.physics.step_s > 0.0 && settings.physics.step_s <= 0.1))
    return Error::inField("step", "must be within (0, 0.1] s");
  return validateCollisionPoolConfig(settings.pool);
}

PhysicsSimulation::PhysicsSimulation(const ElevationModel& model, CollisionMeshSource& source,
                                     const SimulationSettings& settings)
    : model_(model),
      settings_(settings),
      // |p| of the lowest terrain: b + min on an ellipsoid (b = a on a sphere).
      minSurfaceRadius_m_(std::max(1.0, model.shape().polarRadius_m() + model.bounds().min_m)),
      slopeBound_(elevationSlopeBound(model.params())) {
  settings_.physics.planetRadius_m = model.radius_m();
  settings_.physics.flattening = model.shape().flattening();
  world_ = std::make_unique<PhysicsWorld>(settings_.physics);
  pool_ = std::make_unique<CollisionMeshPool>(settings_.pool, source, *world_);
  worker_ = std::make_unique<CollisionSelectionWorker>(RhombusFaceMapping::get(), minSurfaceRadius_m_, settings_.level);
}

PhysicsSimulation::~PhysicsSimulation() {
  worker_.reset();  // joins before the pool and world go
  pool_.reset();
}

uint32_t PhysicsSimulation::addBody(const BodySpec& spec) { return world_->addBody(spec); }

double PhysicsSimulation::surfaceMaxRadius(const glm::dvec3& position_m, double arc_m) const {
  const glm::dvec3 direction = glm::normalize(position_m);
  const NodeId below = nodeAt(RhombusFaceMapping::get().locate(direction), settings_.level);
  if (const CollisionMesh* mesh = pool_->mesh(below);
      mesh && arc_m <= 0.25 * nominalNodeWidth(below.level, model_.radius_m()))
    return mesh->radius.max_m;
  return model_.radius_m() + model_.elevation_m(direction) + slopeBound_ * arc_m;
}

void PhysicsSimulation::applyRound(const CollisionSelectionRound& round) {
  ++stats_.selectionRounds;
  stats_.selection_ms += round.select_ms;
  for (const SelectedCollisionNode& s : round.nodes) pool_->request(s.node, s.distance_m);
}

bool PhysicsSimulation::covered(const ContactCover& cover, const CollisionQuery& swept) const {
  if (cover.radius_m < 0.0 || cover.evictions != pool_->stats().evicted) return false;
  // The selection measures arcs on the lowest surface sphere around a query's direction (see
  // selectCollisionNodes), so the swept cap must lie inside the cover's cap.
  return minSurfaceRadius_m_ * angleBetween_rad(cover.centre_m, swept.position_m) + swept.radius_m <= cover.radius_m;
}

void PhysicsSimulation::makeCover(ContactCover& cover, const CollisionQuery& swept, double speed_m_s,
                                  std::vector<SelectedCollisionNode>& scratch) const {
  // Room for about eight steps of travel, so a falling or rolling body makes a cover every few steps.
  const double pad_m = kCoverPad_m + 8.0 * speed_m_s * settings_.physics.step_s;
  const CollisionQuery query{swept.position_m, swept.radius_m + pad_m};
  scratch.clear();
  selectCollisionNodes(RhombusFaceMapping::get(), minSurfaceRadius_m_, query, settings_.level, scratch);
  cover.radius_m = -1.0;
  double highest_m = 0.0;
  for (const SelectedCollisionNode& s : scratch) {
    const CollisionMesh* mesh = pool_->mesh(s.node);
    if (!mesh) {
      cover.retryStep = stats_.steps + kCoverRetrySteps;
      return;
    }
    highest_m = std::max(highest_m, mesh->radius.max_m);
  }
  cover = {query.position_m, query.radius_m, pool_->stats().evicted, 0, highest_m};
}

void PhysicsSimulation::predictContacts() {
  // The test per body reads only the world and the pool (and writes its own cover), so it runs on
  // the physics threads; the synchronous generations then happen in id order, as if the loop were
  // serial. A body inside its cover needs nothing; otherwise the exact test: its swept sphere
  // against the surface bound, then which nodes under it are missing.
  const double dt = settings_.physics.step_s;
  predictions_.resize(world_->bodyCount());
  covers_.resize(world_->bodyCount());
  world_->threads().run(predictions_.size(), 128, [&](size_t begin, size_t end) {
    std::vector<SelectedCollisionNode> nodes;
    for (size_t id = begin; id < end; ++id) {
      ContactPrediction& p = predictions_[id];
      p.contact = false;
      p.missing.clear();
      const BodyState state = world_->state(uint32_t(id));
      if (state.sleeping) continue;
      const BodyMotion motion{state.position_m, state.velocity_m_s, world_->boundingRadius(uint32_t(id))};
      const CollisionQuery swept = sweptContactQuery(motion, dt, kContactSlack_m);
      ContactCover& cover = covers_[id];
      if (!covered(cover, swept) && stats_.steps >= cover.retryStep)
        makeCover(cover, swept, glm::length(state.velocity_m_s), nodes);
      if (covered(cover, swept)) {
        p.contact = predictsContact(motion, dt, cover.surfaceMax_m + kContactSlack_m);
        continue;
      }
      if (!predictsContact(motion, dt, surfaceMaxRadius(swept.position_m, swept.radius_m) + kContactSlack_m)) continue;
      p.contact = true;
      nodes.clear();
      selectCollisionNodes(RhombusFaceMapping::get(), minSurfaceRadius_m_, swept, settings_.level, nodes);
      for (const SelectedCollisionNode& s : nodes)
        if (!pool_->isResident(s.node)) p.missing.push_back(s);
    }
  });
  for (const ContactPrediction& p : predictions_) {
    stats_.predictedContacts += p.contact ? 1 : 0;
    for (const SelectedCollisionNode& s : p.missing) {
      if (pool_->isResident(s.node)) continue;  // an earlier body's contact generated it
      ++stats_.predictedMissing;
      pool_->requireNow(s.node, s.distance_m);
    }
  }
}

void PhysicsSimulation::submitSelection() {
  std::vector<ObjectQuery> queries;
  queries.reserve(world_->bodyCount());
  // Sleeping bodies need nothing new: the nodes they rest on are pinned by their contacts. A body's
  // selection is reused while it stays within about three rounds of travel (and 1 m) of where it
  // was made.
  const double roundTravel_s = double(3 * kRoundSteps) * settings_.physics.step_s;
  for (uint32_t id = 0; id < world_->bodyCount(); ++id) {
    const BodyState state = world_->state(id);
    if (state.sleeping) continue;
    queries.push_back({id,
                       {state.position_m, world_->boundingRadius(id) + settings_.interestRadius_m},
                       kSelectionReuse_m + glm::length(state.velocity_m_s) * roundTravel_s});
  }
  pendingRound_ = worker_->submit(std::move(queries));
  roundSubmitStep_ = stats_.steps;
}

void PhysicsSimulation::settleSelection() {
  if (pendingRound_ == 0) submitSelection();
  worker_->waitFor(pendingRound_);
  if (worker_->take(round_)) applyRound(round_);
  pendingRound_ = 0;
}

void PhysicsSimulation::prepare() {
  settleSelection();
  pool_->generateQueued();
}

void PhysicsSimulation::step() {
  const auto start = std::chrono::steady_clock::now();
  const double startCpu = threadCpu_ms();
  pool_->beginStep(stats_.steps + 1);
  // A round is applied a fixed number of steps after it was submitted (waiting for the worker if it
  // is late), so which step a request enters the queue never depends on thread timing.
  if (pendingRound_ != 0 && stats_.steps >= roundSubmitStep_ + kRoundSteps) settleSelection();
  predictContacts();
  pool_->dispatch();
  const auto physicsStart = std::chrono::steady_clock::now();
  const double physicsStartCpu = threadCpu_ms();
  world_->step();
  stats_.physics_ms.push_back(msSince(physicsStart));
  stats_.physicsCpu_ms.push_back(threadCpu_ms() - physicsStartCpu);
  for (uint32_t id = 0; id < world_->bodyCount(); ++id)
    for (const NodeId& node : world_->contactNodes(id)) pool_->pin(node);
  if (pendingRound_ == 0) submitSelection();
  ++stats_.steps;
  stats_.step_ms.push_back(msSince(start));
  stats_.stepCpu_ms.push_back(threadCpu_ms() - startCpu);
}

}  // namespace globe
