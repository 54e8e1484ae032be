// Collision-mesh generation latency on the GPU (lavapipe here): one synchronous mesh (a predicted
// contact: dispatch, wait, read back the positions) and a batch of asynchronous ones.
//
//   build/release/bin/engine_bench --benchmark_filter='CollisionMesh'
#include "bench_support.h"
#include "engine/collision/gpu_collision_mesh_source.h"

#include <benchmark/benchmark.h>

namespace globe {
namespace {

void BM_CollisionMeshGpuSync(benchmark::State& state) {
  GpuCollisionMeshSource source(bench::device(), bench::earthlikeModel(), uint32_t(state.range(0)), 16);
  uint32_t x = 0;
  for (auto _ : state) benchmark::DoNotOptimize(source.generateNow({4, 14, 8000 + (x++ % 64), 9000}));
}
BENCHMARK(BM_CollisionMeshGpuSync)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);

// 16 meshes started together and collected two steps later (waited for): ms per batch.
void BM_CollisionMeshGpuBatch16(benchmark::State& state) {
  GpuCollisionMeshSource source(bench::device(), bench::earthlikeModel(), uint32_t(state.range(0)), 16);
  std::vector<NodeId> nodes;
  for (uint32_t k = 0; k < 16; ++k) nodes.push_back({4, 14, 8000 + k, 9000});
  std::vector<CollisionMesh> meshes;
  for (auto _ : state) {
    source.generate(nodes);
    meshes.clear();
    source.collect(meshes);
    source.collect(meshes);
    benchmark::DoNotOptimize(meshes.data());
  }
  state.counters["meshes_per_s"] = benchmark::Counter(16.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CollisionMeshGpuBatch16)->Arg(32)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace globe
