// Physics steps on the collision meshes (CPU reference meshes; the GPU ones are the same data):
// ms per step for 1, 10, 100, 1000 bodies scattered over the planet or clustered in one valley,
// with their meshes resident (generation is measured separately: BM_CollisionMeshCpu here,
// BM_CollisionMeshGpu in engine_bench, and end to end by `globe physics`, docs/physics.md).
//
//   build/release/bin/planet_bench --benchmark_filter='Physics|CollisionMesh'
#include "planet/analysis/percentile.h"
#include "planet/camera/camera.h"
#include "planet/model/planet_file.h"
#include "planet/physics/body_groups.h"
#include "planet/physics/physics_scenario.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>

namespace globe {
namespace {

const ElevationModel& model() {
  static const ElevationModel m = [] {
    auto planet = loadPlanetFile(GLOBE_SOURCE_DIR "/assets/planets/earthlike.toml");
    if (!planet) std::abort();
    return ElevationModel(*planet);
  }();
  return m;
}

double processCpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// range(0): bodies; range(1): 1 = clustered in one 100 m valley. The timed steps start once every
// mesh the bodies asked for is resident (untimed warm-up), with the bodies 1-100 m up and falling:
// 600 steps (5 s) cover falling, impacts and settling.
void BM_PhysicsStep(benchmark::State& state) {
  CpuCollisionMeshSource source(model(), 32);
  SimulationSettings settings;
  settings.pool.dispatchBudget = 64;
  PhysicsSimulation sim(model(), source, settings);
  ScenarioSettings scenario;
  scenario.bodies = uint32_t(state.range(0));
  scenario.clustered = state.range(1) != 0;
  scenario.clusterCentre = directionFromLatLon(10.0, 20.0);
  std::vector<PlacedBody> placed = placeBodies(model(), scenario);
  addPlacedBodies(sim, model(), placed);
  sim.settleSelection();
  for (int warm = 0; warm < 2000 && (sim.pool().stats().queued > 0 || warm < 8); ++warm) sim.step();
  const size_t first = sim.stats().step_ms.size();
  const double processStart_ms = processCpu_ms();
  const CollisionPoolStats before = sim.pool().stats();
  for (auto _ : state) sim.step();
  // Every thread's CPU time (the physics threads and the selection worker) per step: the work, as
  // opposed to the wall time a step takes, which on a shared machine includes waiting for a core.
  state.counters["process_cpu_ms"] = (processCpu_ms() - processStart_ms) / double(state.iterations());
  std::vector<double> steps(sim.stats().step_ms.begin() + std::ptrdiff_t(first), sim.stats().step_ms.end());
  std::sort(steps.begin(), steps.end());
  state.counters["p50_ms"] = nearestRankPercentile(steps, 50);
  state.counters["p99_ms"] = nearestRankPercentile(steps, 99);
  state.counters["max_ms"] = steps.back();
  std::vector<double> cpu(sim.stats().stepCpu_ms.begin() + std::ptrdiff_t(first), sim.stats().stepCpu_ms.end());
  std::sort(cpu.begin(), cpu.end());
  state.counters["cpu_p50_ms"] = nearestRankPercentile(cpu, 50);
  state.counters["cpu_p99_ms"] = nearestRankPercentile(cpu, 99);
  state.counters["cpu_max_ms"] = cpu.back();
  // Bullet's step alone (the rest of a step: predicted contacts, mesh generation and BVH builds).
  std::vector<double> world(sim.stats().physicsCpu_ms.begin() + std::ptrdiff_t(first), sim.stats().physicsCpu_ms.end());
  std::sort(world.begin(), world.end());
  state.counters["world_cpu_p50_ms"] = nearestRankPercentile(world, 50);
  state.counters["world_cpu_max_ms"] = world.back();
  state.counters["pool_MiB"] = sim.pool().stats().residentMiB();
  state.counters["meshes"] = double(sim.pool().stats().resident);
  state.counters["sync"] = double(sim.pool().stats().generatedSync);
  state.counters["async"] = double(sim.pool().stats().generatedAsync);
  state.counters["evicted"] = double(sim.pool().stats().evicted);
  // Meshes that arrived during the timed steps (each a BVH build).
  state.counters["timed_arrivals"] = double(sim.pool().stats().generatedAsync + sim.pool().stats().generatedSync -
                                            before.generatedAsync - before.generatedSync);
  uint32_t asleep = 0;  // Bullet deactivated them: below the sleep thresholds for 2 s
  for (uint32_t id = 0; id < sim.world().bodyCount(); ++id) asleep += sim.world().state(id).sleeping ? 1u : 0u;
  state.counters["asleep"] = double(asleep);
}
BENCHMARK(BM_PhysicsStep)->ArgsProduct({{1, 10, 100, 1000}, {0, 1}})->Iterations(600)->Unit(benchmark::kMillisecond);

// Grouping the bodies into worlds (every 4 steps, on the stepping thread): range(0) bodies,
// range(1) 1 = clustered, with the reach of a body falling at 20 m/s.
void BM_GroupBodies(benchmark::State& state) {
  ScenarioSettings scenario;
  scenario.bodies = uint32_t(state.range(0));
  scenario.clustered = state.range(1) != 0;
  scenario.clusterCentre = directionFromLatLon(10.0, 20.0);
  std::vector<BodyReach> reach;
  for (const PlacedBody& b : placeBodies(model(), scenario))
    reach.push_back({b.spec.position_m, 1.0 + 20.0 * 8.0 / 120.0});
  for (auto _ : state) benchmark::DoNotOptimize(groupBodies(reach));
}
BENCHMARK(BM_GroupBodies)->ArgsProduct({{1000}, {0, 1}})->Unit(benchmark::kMicrosecond);

void BM_CollisionMeshCpu(benchmark::State& state) {
  CpuCollisionMeshSource source(model(), uint32_t(state.range(0)));
  uint32_t x = 0;
  for (auto _ : state) benchmark::DoNotOptimize(source.generateNow({4, 14, 8000 + (x++ % 64), 9000}));
}
BENCHMARK(BM_CollisionMeshCpu)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace globe
