// Tessellation quality and mapping cost (docs/tessellation.md). One command prints the table:
//   build/tess/bin/planet_bench --benchmark_filter=Tessellation
// Tessellation/Quality/<mapping>: one measurement of the 128-cells-per-edge grid per iteration; the
//   counters are the table's columns (area max/min, area CV, angle min/max in degrees, edge max/min).
// Tessellation/UnitPoint/<mapping>: cost of one unit-point evaluation over the 129 × 129 grid points of
//   a face ("face": dyadic depth <= 7) and of a level-20 node ("deep": depth <= 27, what a leaf node
//   of an Earth-sized planet's grid costs the subdivision mapping).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "planet/geometry/triacontahedron.h"
#include "planet/research/subdivision_face_mapping.h"
#include "planet/research/tessellation_quality.h"

namespace globe {
namespace {

constexpr int kCellsPerEdge = 128;

struct MappingCase {
  const char* name;
  int faces;
  UnitPointFunction point;
};

MappingCase mappingCase(int index) {
  switch (index) {
    case 0:
      return {"rhombus_bilinear", kFaceCount,
              [](int f, double u, double v) { return RhombusFaceMapping::get().unitPoint(f, u, v); }};
    case 1:
      return {"rhombus_subdivision", kFaceCount,
              [](int f, double u, double v) { return SubdivisionFaceMapping::get().unitPoint(f, u, v); }};
    case 2:
      return {"cube_gnomonic", 6,
              [](int f, double u, double v) { return cubeSpherePoint(CubeSphereWarp::kGnomonic, f, u, v); }};
    default:
      return {"cube_equiangular", 6,
              [](int f, double u, double v) { return cubeSpherePoint(CubeSphereWarp::kEquiAngular, f, u, v); }};
  }
}

void quality(benchmark::State& state, int index) {
  const MappingCase c = mappingCase(index);
  TessellationMetrics m;
  for (auto _ : state) {
    m = measureTessellation(c.faces, c.point, kCellsPerEdge);
    benchmark::DoNotOptimize(m.areaMax_sr + 0.0);  // an rvalue: the value itself stays untouched
  }
  state.counters["faces"] = m.faceCount;
  state.counters["cells"] = static_cast<double>(m.cellCount);
  state.counters["area_max_over_min"] = m.areaRatio();
  state.counters["area_cv"] = m.areaCv();
  state.counters["angle_min_deg"] = m.angleMin_deg;
  state.counters["angle_max_deg"] = m.angleMax_deg;
  state.counters["angle_mean_abs_dev_deg"] = m.angleMeanAbsDeviation_deg;
  state.counters["edge_max_over_min"] = m.edgeRatio();
  state.counters["total_area_sr"] = m.totalArea_sr;  // 4π = 12.566
}

// Concrete calls (not through std::function) so the timing is the mapping's, not the wrapper's.
template <typename Point>
void unitPointCost(benchmark::State& state, Point point, int faces, bool deep) {
  // deep: the grid of node (level 20, x = y = 2^19 + 12345) — u = (x · 128 + i) / 2^27.
  const double scale = deep ? 1.0 / 134217728.0 : 1.0 / 128.0;
  const double base = deep ? (524288.0 + 12345.0) * 128.0 : 0.0;
  int face = 0;
  for (auto _ : state) {
    for (int j = 0; j <= kCellsPerEdge; ++j) {
      for (int i = 0; i <= kCellsPerEdge; ++i) {
        benchmark::DoNotOptimize(point(face, (base + i) * scale, (base + j) * scale));
      }
    }
    face = (face + 1) % faces;
  }
  state.SetItemsProcessed(state.iterations() * (kCellsPerEdge + 1) * (kCellsPerEdge + 1));
  // Seconds per point, shown with an SI prefix ("8n" = 8 ns).
  state.counters["t_per_point"] =
      benchmark::Counter(static_cast<double>((kCellsPerEdge + 1) * (kCellsPerEdge + 1)),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// What the subdivision mapping would cost the engine if a node's whole grid were generated at once
// (as the payload generator does), level by level from the node's four corners: every new point is
// one normalise(a + b) or one normalise of a four-point sum, ~1 normalisation per point instead of
// the per-point descent. Checked bit-for-bit against SubdivisionFaceMapping::unitPoint.
glm::dvec3 normalised(const glm::dvec3& p) {
  const double inverseLength = 1.0 / std::sqrt((p.x * p.x + p.y * p.y) + p.z * p.z);
  return {p.x * inverseLength, p.y * inverseLength, p.z * inverseLength};
}

void subdivideGrid(std::vector<glm::dvec3>& g, int n) {
  const auto at = [&](int i, int j) -> glm::dvec3& { return g[static_cast<size_t>(j * (n + 1) + i)]; };
  for (int step = n; step > 1; step /= 2) {
    const int half = step / 2;
    for (int j = 0; j <= n; j += step) {
      for (int i = 0; i < n; i += step) at(i + half, j) = normalised(at(i, j) + at(i + step, j));
    }
    for (int j = 0; j < n; j += step) {
      for (int i = 0; i <= n; i += step) at(i, j + half) = normalised(at(i, j + step) + at(i, j));
    }
    for (int j = 0; j < n; j += step) {
      for (int i = 0; i < n; i += step) {
        at(i + half, j + half) = normalised((at(i, j) + at(i + step, j)) + (at(i + step, j + step) + at(i, j + step)));
      }
    }
  }
}

void subdivisionGridCost(benchmark::State& state) {
  const SubdivisionFaceMapping& m = SubdivisionFaceMapping::get();
  const int n = kCellsPerEdge;
  std::vector<glm::dvec3> grid(static_cast<size_t>((n + 1) * (n + 1)));
  const auto setCorners = [&] {
    grid[0] = m.unitPoint(5, 0.0, 0.0);
    grid[static_cast<size_t>(n)] = m.unitPoint(5, 1.0, 0.0);
    grid[static_cast<size_t>(n * (n + 1))] = m.unitPoint(5, 0.0, 1.0);
    grid[static_cast<size_t>(n * (n + 1) + n)] = m.unitPoint(5, 1.0, 1.0);
  };
  setCorners();
  subdivideGrid(grid, n);
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const glm::dvec3 expected = m.unitPoint(5, i / static_cast<double>(n), j / static_cast<double>(n));
      if (std::memcmp(&expected, &grid[static_cast<size_t>(j * (n + 1) + i)], sizeof expected) != 0) {
        state.SkipWithError("grid subdivision differs from SubdivisionFaceMapping::unitPoint");
        return;
      }
    }
  }
  for (auto _ : state) {
    setCorners();
    subdivideGrid(grid, n);
    benchmark::DoNotOptimize(grid.data());
  }
  state.counters["t_per_point"] =
      benchmark::Counter(static_cast<double>((n + 1) * (n + 1)),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <typename Mapping>
void locateCost(benchmark::State& state, const Mapping& mapping) {
  std::vector<glm::dvec3> directions;
  for (int i = 0; i < 256; ++i) {
    directions.push_back(
        mapping.unitPoint(i % kFaceCount, ((i * 37) % 256 + 0.5) / 256.0, ((i * 91) % 256 + 0.5) / 256.0));
  }
  size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(mapping.locate(directions[k]).u + 0.0);
    k = (k + 1) % directions.size();
  }
}

void registerAll() {
  benchmark::RegisterBenchmark("Tessellation/Locate/rhombus_bilinear",
                               [](benchmark::State& s) { locateCost(s, RhombusFaceMapping::get()); });
  benchmark::RegisterBenchmark("Tessellation/Locate/rhombus_subdivision", [](benchmark::State& s) {
    locateCost(s, SubdivisionFaceMapping::get());
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("Tessellation/UnitPoint/rhombus_subdivision/whole_grid", subdivisionGridCost);
  for (int i = 0; i < 4; ++i) {
    benchmark::RegisterBenchmark((std::string("Tessellation/Quality/") + mappingCase(i).name).c_str(), quality, i)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
  const auto rhombus = [](int f, double u, double v) { return RhombusFaceMapping::get().unitPoint(f, u, v); };
  const auto subdivision = [](int f, double u, double v) { return SubdivisionFaceMapping::get().unitPoint(f, u, v); };
  const auto gnomonic = [](int f, double u, double v) { return cubeSpherePoint(CubeSphereWarp::kGnomonic, f, u, v); };
  const auto equiAngular = [](int f, double u, double v) {
    return cubeSpherePoint(CubeSphereWarp::kEquiAngular, f, u, v);
  };
  for (bool deep : {false, true}) {
    const std::string suffix = deep ? "/deep" : "/face";
    benchmark::RegisterBenchmark(("Tessellation/UnitPoint/rhombus_bilinear" + suffix).c_str(),
                                 [=](benchmark::State& s) { unitPointCost(s, rhombus, kFaceCount, deep); });
    benchmark::RegisterBenchmark(("Tessellation/UnitPoint/rhombus_subdivision" + suffix).c_str(),
                                 [=](benchmark::State& s) { unitPointCost(s, subdivision, kFaceCount, deep); });
    if (deep) continue;  // the cube spheres cost the same at any depth
    benchmark::RegisterBenchmark("Tessellation/UnitPoint/cube_gnomonic/face",
                                 [=](benchmark::State& s) { unitPointCost(s, gnomonic, 6, false); });
    benchmark::RegisterBenchmark("Tessellation/UnitPoint/cube_equiangular/face",
                                 [=](benchmark::State& s) { unitPointCost(s, equiAngular, 6, false); });
  }
}

const int kRegistered = (registerAll(), 0);

}  // namespace
}  // namespace globe
