// Generation on the GPU (lavapipe here): samples per second of the double elevation kernel, and
// milliseconds per node payload at grid 16/32/64/128 in batches, warm and cold.
//
//   build/release/bin/engine_bench --benchmark_filter='Gpu'
// Compare with the CPU reference and libnoise: build/release/bin/planet_bench --benchmark_filter='Elevation|Libnoise'
#include "bench_support.h"
#include "engine/generation/elevation_sampler.h"
#include "engine/generation/gpu_payload_generator.h"
#include "planet/model/planet_file.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

namespace globe {
namespace {

using bench::device;
const ElevationModel& model() { return bench::earthlikeModel(); }

// Earthlike's layers on WGS84 (a = 6378137 m, f = 1 / 298.257223563): the payload's ellipsoid placement.
const ElevationModel& wgs84Model() {
  static const ElevationModel m = [] {
    PlanetDescription p = bench::earthlike();
    p.radius_m = 6378137.0;
    p.flattening = 1.0 / 298.257223563;
    return ElevationModel(p);
  }();
  return m;
}

// Earthlike without its land cover: the colour ramp's albedo, no masks (docs/rendering.md, "Land cover").
const ElevationModel& noLandCoverModel() {
  static const ElevationModel m = [] {
    PlanetDescription p = bench::earthlike();
    p.land_cover = {};
    return ElevationModel(p);
  }();
  return m;
}

// The same 4096 directions as bench/planet/elevation_bench.cpp, repeated to fill a dispatch.
std::vector<glm::dvec3> directions(size_t count) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> uz(-1.0, 1.0), uphi(0.0, 6.283185307179586);
  std::vector<glm::dvec3> base;
  for (int i = 0; i < 4096; ++i) {
    const double z = uz(rng), phi = uphi(rng), r = std::sqrt(1.0 - z * z);
    base.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  std::vector<glm::dvec3> out(count);
  for (size_t i = 0; i < count; ++i) out[i] = base[i % base.size()];
  return out;
}

void BM_GpuElevationSamples(benchmark::State& state) {
  const uint32_t count = uint32_t(state.range(0));
  ElevationSampler sampler(device(), model().params(), count);
  auto dirs = directions(count);
  sampler.sample(dirs);  // warm-up: the first dispatch JIT-compiles the pipeline
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    device().submitAndWait([&](VkCommandBuffer cmd) { sampler.record(cmd, count); });
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * count);
}
BENCHMARK(BM_GpuElevationSamples)->Arg(1 << 18)->UseManualTime()->Unit(benchmark::kMillisecond);

std::vector<NodeId> benchNodes(size_t count) {
  std::mt19937_64 rng(7);
  std::vector<NodeId> nodes;
  for (size_t k = 0; k < count; ++k) {
    uint8_t level = uint8_t(8 + rng() % 12);
    uint32_t side = 1u << level;
    nodes.push_back({uint8_t(rng() % 30), level, uint32_t(rng() % side), uint32_t(rng() % side)});
  }
  return nodes;
}

// Warm: ms per node payload, `batch` nodes per submit (the pool's budget is 8 per frame); third
// argument 0 on earthlike's sphere, 1 on WGS84, 2 on earthlike without land cover; fourth the normal map's scale (0:
// none, as collision meshes; 1, 2, 4, 8: the renderer's payloads, docs/rendering.md "Surface textures").
void BM_GpuPayload(benchmark::State& state) {
  const uint32_t cells = uint32_t(state.range(0));
  const uint32_t batch = uint32_t(state.range(1));
  const ElevationModel& planet = state.range(2) == 0   ? model()
                                 : state.range(2) == 1 ? wgs84Model()
                                                       : noLandCoverModel();
  GpuPayloadGenerator gen(device(), planet, cells, batch, 1, GenerationPrecision::kDouble, false,
                          uint32_t(state.range(3)));
  gen.reserveSlots(batch);
  auto nodes = benchNodes(batch);
  std::vector<GenerationJob> jobs;
  for (uint32_t k = 0; k < batch; ++k) jobs.push_back({nodes[k], k});
  std::vector<GenerationResult> done;
  gen.generate(jobs);  // warm-up
  gen.waitIdle();
  gen.collect(done);
  double gpuBefore = gen.gpuTime_ms();
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    gen.generate(jobs);
    gen.waitIdle();
    done.clear();
    gen.collect(done);
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  double perNode = (gen.gpuTime_ms() - gpuBefore) / double(state.iterations() * batch);
  state.counters["gpu_ms_per_node"] = perNode;
  state.counters["samples_per_node"] = double((cells + 3) * (cells + 3));
  state.counters["gpu_samples_per_s"] = double((cells + 3) * (cells + 3)) / (perNode * 1e-3);
  state.SetItemsProcessed(int64_t(state.iterations()) * batch);
}
BENCHMARK(BM_GpuPayload)
    ->ArgsProduct({{16, 32, 64, 128}, {8, 32}, {0}, {0}})
    ->ArgsProduct({{16}, {8}, {0}, {1, 2, 4}})
    ->ArgsProduct({{8}, {8}, {0, 2}, {0, 4, 8}})  // balanced's grid, with and without land cover
    ->ArgsProduct({{16}, {8, 32}, {2}, {0, 1}})
    ->Args({64, 32, 1, 0})
    ->Args({128, 32, 1, 0})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

// Cold: pipeline creation plus the first dispatch (JIT compilation; Mesa's disk cache may help —
// set MESA_SHADER_CACHE_DISABLE=true for a truly cold figure).
void BM_GpuPayloadColdFirstDispatch(benchmark::State& state) {
  auto nodes = benchNodes(8);
  std::vector<GenerationJob> jobs;
  for (uint32_t k = 0; k < 8; ++k) jobs.push_back({nodes[k], k});
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    GpuPayloadGenerator gen(device(), model(), 64, 8, 1);
    gen.reserveSlots(8);
    gen.generate(jobs);
    gen.waitIdle();
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
}
BENCHMARK(BM_GpuPayloadColdFirstDispatch)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace globe
