// The design decision of [Frasson 2018, §3.3], measured on the CPU (docs/tradeoffs.md): per vertex per
// frame, either read a stored node-relative float position (what globe does: offset + position,
// minus the camera as a float pair), or re-project a stored height in double every frame (face
// mapping of the grid point, normalise, scale by R + h, subtract the camera in double, round).
// lavapipe runs vertex shaders on the same CPU cores with the same SIMD, so the ratio is indicative
// of the vertex-stage cost there; not a GPU measurement.
//
//   build/release/bin/engine_bench --benchmark_filter=VertexWork
#include <benchmark/benchmark.h>

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace {

constexpr int kCells = 32;  // vertices per node: 33 x 33
constexpr int kNodes = 256;
constexpr int kSide = kCells + 1;

void BM_VertexWorkStoredFloatPositions(benchmark::State& state) {
  std::vector<glm::vec3> positions(size_t(kSide) * kSide * kNodes);
  for (size_t i = 0; i < positions.size(); ++i)
    positions[i] = glm::vec3(float(i % 97) * 0.1f, float(i % 89) * 0.1f, float(i % 83) * 0.1f);
  std::vector<glm::vec3> offsets(kNodes, glm::vec3(1000.0f, -2000.0f, 500.0f));
  const glm::vec3 high(12.5f, -3.25f, 7.0f), low(1e-6f, -2e-6f, 3e-7f);
  for (auto _ : state) {
    glm::vec3 sum(0.0f);
    for (int n = 0; n < kNodes; ++n)
      for (int v = 0; v < kSide * kSide; ++v) {
        glm::vec3 world = offsets[size_t(n)] + positions[size_t(n) * kSide * kSide + size_t(v)];
        sum += (world - high) - low;
      }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * kNodes * kSide * kSide);
}
BENCHMARK(BM_VertexWorkStoredFloatPositions);

void BM_VertexWorkReprojectedDouble(benchmark::State& state) {
  std::vector<float> heights(size_t(kSide) * kSide * kNodes);
  for (size_t i = 0; i < heights.size(); ++i) heights[i] = float(i % 1000) * 3.0f;
  struct NodeCorners {
    glm::dvec3 c0, e1, e3;
  };
  std::vector<NodeCorners> nodes(kNodes, {glm::dvec3(0.3, 0.5, 0.6), glm::dvec3(1e-4, 0, 0), glm::dvec3(0, 1e-4, 0)});
  const double radius = 6371000.0;
  const glm::dvec3 camera(1.9e6, 3.2e6, 3.8e6);
  for (auto _ : state) {
    glm::vec3 sum(0.0f);
    for (int n = 0; n < kNodes; ++n) {
      const NodeCorners& c = nodes[size_t(n)];
      for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
          double u = double(i) / kCells, v = double(j) / kCells;
          glm::dvec3 p = (c.c0 + u * c.e1) + v * c.e3;  // face mapping (bilinear on the rhombus)
          double s = 1.0 / std::sqrt(glm::dot(p, p));   // normalise
          double h = heights[size_t(n) * kSide * kSide + size_t(j * kSide + i)];
          glm::dvec3 world = p * (s * (radius + h));
          sum += glm::vec3(world - camera);
        }
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * kNodes * kSide * kSide);
}
BENCHMARK(BM_VertexWorkReprojectedDouble);

}  // namespace
