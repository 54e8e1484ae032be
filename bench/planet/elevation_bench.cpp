// Elevation on the CPU: samples per second of the double reference (12 octaves, earthlike) and of
// libnoise's Perlin module (12 octaves, standard quality, double), same points, 1 and 2 threads;
// plus the float-vs-double error table of docs/elevation.md (reported as counters).
//
//   build/elev/bin/planet_bench --benchmark_filter='Elevation|Libnoise'
#include <benchmark/benchmark.h>

#include <libnoise/noise.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <glm/geometric.hpp>
#include <random>
#include <string>
#include <vector>

#include "planet/gdal/gdal_readers.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"

namespace {

using globe::ElevationModel;
using globe::PlanetDescription;

// bench/CMakeLists.txt defines no source directory: find assets/ from this file's path, or from
// $GLOBE_PLANET when set.
PlanetDescription earthlike() {
  const char* env = std::getenv("GLOBE_PLANET");
  const std::string path =
      env != nullptr
          ? std::string(env)
          : (std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / globe::kDefaultPlanetFile)
                .string();
  globe::installGdalReaders();  // $GLOBE_PLANET may name a planet with real sources
  auto r = globe::loadPlanetFile(path);
  if (!r.ok()) {
    std::fprintf(stderr, "%s\n", r.error().format().c_str());
    std::abort();
  }
  return *r;
}

// The same 4096 uniformly distributed unit directions for every benchmark.
const std::vector<glm::dvec3>& directions() {
  static const std::vector<glm::dvec3> dirs = [] {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> uz(-1.0, 1.0), uphi(0.0, 6.283185307179586);
    std::vector<glm::dvec3> out;
    for (int i = 0; i < 4096; ++i) {
      const double z = uz(rng), phi = uphi(rng), r = std::sqrt(1.0 - z * z);
      out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
    return out;
  }();
  return dirs;
}

void BM_ElevationCpuReference(benchmark::State& state) {
  static const ElevationModel model(earthlike());
  const auto& dirs = directions();
  std::size_t i = static_cast<std::size_t>(state.thread_index()) * 997;
  for (auto _ : state) {
    benchmark::DoNotOptimize(model.elevation_m(dirs[i % dirs.size()]));
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ElevationCpuReference)->Threads(1)->Threads(2)->UseRealTime();

// libnoise Perlin over the same wavelength span as earthlike's 12 octaves (4000 km down to 0.64 m:
// lacunarity 6.25e6^(1/11) = 4.15), evaluated at the same points in metres.
void BM_LibnoisePerlin(benchmark::State& state) {
  noise::module::Perlin perlin;
  perlin.SetOctaveCount(12);
  perlin.SetNoiseQuality(noise::QUALITY_STD);
  perlin.SetFrequency(1.0 / 4.0e6);
  perlin.SetLacunarity(4.15);
  perlin.SetPersistence(0.5);
  const auto& dirs = directions();
  const double radius = 6371000.0;
  std::size_t i = static_cast<std::size_t>(state.thread_index()) * 997;
  for (auto _ : state) {
    const glm::dvec3 p = dirs[i % dirs.size()] * radius;
    benchmark::DoNotOptimize(perlin.GetValue(p.x, p.y, p.z));
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LibnoisePerlin)->Threads(1)->Threads(2)->UseRealTime();

// Float vs double, not a speed measurement: |h_float - h_double| over the 4096 points, and the error
// of the elevation difference between points 1 m apart (what normals see). Arg 0: radius (m);
// arg 1: -1 for all earthlike layers, k for layer k alone (unmodulated).
void BM_ElevationFloatError(benchmark::State& state) {
  PlanetDescription planet = earthlike();
  planet.radius_m = static_cast<double>(state.range(0));
  const auto layer = state.range(1);  // -1: all layers; k: only layer k (unmodulated)
  if (layer >= 0) {
    globe::ElevationLayer only = planet.layers[static_cast<std::size_t>(layer)];
    only.modulated_by = -1;
    planet.layers = {only};
  }
  const ElevationModel model(planet);
  const auto& dirs = directions();
  double max_err = 0.0, sum2 = 0.0, max_diff_err = 0.0, signal2 = 0.0, diff2 = 0.0, diff_err2 = 0.0;
  for (auto _ : state) {
    for (const glm::dvec3& d : dirs) {
      const double h = model.elevation_m(d);
      const double e = std::abs(static_cast<double>(model.elevationFloat_m(glm::vec3(d))) - h);
      max_err = std::max(max_err, e);
      sum2 += e * e;
      signal2 += h * h;
      // A neighbour 1 m away along a tangent.
      const glm::dvec3 t = glm::normalize(glm::cross(d, glm::dvec3(0.0, 0.0, 1.0)));
      const glm::dvec3 d2 = glm::normalize(d + t * (1.0 / planet.radius_m));
      const double dh = model.elevation_m(d2) - h;
      const double dh_f = static_cast<double>(model.elevationFloat_m(glm::vec3(d2))) -
                          static_cast<double>(model.elevationFloat_m(glm::vec3(d)));
      max_diff_err = std::max(max_diff_err, std::abs(dh_f - dh));
      diff2 += dh * dh;
      diff_err2 += (dh_f - dh) * (dh_f - dh);
    }
  }
  const double n = static_cast<double>(dirs.size() * static_cast<std::size_t>(state.iterations()));
  state.counters["max_err_m"] = max_err;
  state.counters["rms_err_m"] = std::sqrt(sum2 / n);
  state.counters["rms_elev_m"] = std::sqrt(signal2 / n);
  state.counters["max_1m_diff_err_m"] = max_diff_err;
  state.counters["rms_1m_diff_err_m"] = std::sqrt(diff_err2 / n);
  state.counters["rms_1m_diff_m"] = std::sqrt(diff2 / n);
}
BENCHMARK(BM_ElevationFloatError)
    ->ArgNames({"radius_m", "layer"})
    ->Args({1000, -1})
    ->Args({6371000, -1})
    ->Args({6371000, 0})
    ->Args({6371000, 1})
    ->Args({6371000, 2})
    ->Args({70000000, -1})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
