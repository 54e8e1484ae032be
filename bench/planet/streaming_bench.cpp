// Streaming under the default budget (docs/streaming.md): a straight great-circle flight at 60 Hz,
// camera looking forward and 10° down, R = 6371 km, default LodConfig and StreamingConfig, the fake
// generator (1-3 frames per payload, 64 KiB slots). The view converges at the start point first, so
// the counters describe steady streaming, not the initial load. Counters:
//   lat_p50/p90/p99/max  frames from the view's first request of a node to resident (pool histogram;
//                        the last bucket, 63, means ">= 63")
//   disp_mean/max        generations started per frame (budget 8); pf_share: prefetch's part of them
//   queue_mean/max       requests left waiting after dispatch (visible + prefetch)
//   fallback_mean        drawn nodes per frame whose children were wanted but not resident (pops)
//   resident_MiB         mean resident + in-flight payload memory
// Each benchmark is one whole flight (Iterations(1)); the time is the CPU cost of selection + pool.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "planet/camera/camera.h"
#include "planet/lod/selection.h"
#include "planet/streaming/payload_pool.h"
#include "tests/support/fake_payload_generator.h"

namespace globe {
namespace {

constexpr double kRadius_m = 6371000.0;
constexpr double kFrameRate_Hz = 60.0;
constexpr int kFlightFrames = 1200;  // 20 s

// Pose at `distance_m` along the great circle through (lat0, lon0) with initial heading heading0.
GeodeticPose poseAlong(double distance_m, double altitude_m, double pitch_deg) {
  const double lat0 = 35.0 * std::numbers::pi / 180.0, lon0 = 8.0 * std::numbers::pi / 180.0;
  const double heading0 = 60.0 * std::numbers::pi / 180.0;
  const glm::dvec3 a(std::cos(lat0) * std::cos(lon0), std::cos(lat0) * std::sin(lon0), std::sin(lat0));
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), a));
  const glm::dvec3 north = glm::cross(a, east);
  const glm::dvec3 b = std::cos(heading0) * north + std::sin(heading0) * east;  // initial tangent
  const double theta = distance_m / kRadius_m;
  const glm::dvec3 p = std::cos(theta) * a + std::sin(theta) * b;
  const glm::dvec3 t = -std::sin(theta) * a + std::cos(theta) * b;  // direction of travel
  const glm::dvec2 latLon = latLonFromPosition(p);
  const glm::dvec3 e = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), p));
  const glm::dvec3 n = glm::cross(p, e);
  const double heading = std::atan2(glm::dot(t, e), glm::dot(t, n)) * 180.0 / std::numbers::pi;
  return {latLon.x, latLon.y, altitude_m, std::fmod(heading + 360.0, 360.0), pitch_deg, 0.0};
}

void flight(benchmark::State& state, double altitude_m, double speed_mps, bool prefetch) {
  LodConfig lod;
  lod.prefetch.enabled = prefetch;
  const StreamingConfig streaming;
  for (auto _ : state) {
    FakePayloadGenerator generator(64 * 1024, kRadius_m,
                                   {kRadius_m + lod.minElevation_m, kRadius_m + lod.maxElevation_m});
    auto pool = PayloadPool::create(streaming, generator, kRadius_m);
    auto selector = LodSelector::create(lod);
    if (!pool || !selector) {
      state.SkipWithError("bad config");
      return;
    }
    Selection selection;
    uint64_t frame = 0;
    const auto step = [&](const GeodeticPose& pose) {
      ++frame;
      generator.tick();
      const Camera cam = cameraFromPose(pose, kRadius_m, kRadius_m, 16.0 / 9.0);
      (*pool)->beginFrame(frame, cam.position_m, frame > 2 ? frame - 2 : 0);
      const auto frustum = Frustum::fromViewProjection(cam.projection() * cam.viewFromWorld(glm::dvec3(0.0)));
      (void)selector->select({cam.position_m, &*frustum}, **pool, selection);
      (*pool)->markUsed(selection.nodes);
      (*pool)->dispatch();
    };
    // Converge at the start (the view and its prefetch), then measure the flight alone.
    for (int k = 0; k < 3000; ++k) {
      step(poseAlong(0.0, altitude_m, -10.0));
      if (selection.stats.fallbacks == 0 && (*pool)->stats().inFlight == 0 && (*pool)->stats().dispatched == 0) break;
    }
    const std::vector<uint64_t> before((*pool)->latencyHistogram().begin(), (*pool)->latencyHistogram().end());
    double dispatched = 0, prefetchDispatched = 0, queue = 0, fallbacks = 0, mib = 0;
    uint32_t maxDispatched = 0, maxQueue = 0;
    for (int f = 1; f <= kFlightFrames; ++f) {
      step(poseAlong(speed_mps * f / kFrameRate_Hz, altitude_m, -10.0));
      const StreamingStats& s = (*pool)->stats();
      dispatched += s.dispatched;
      prefetchDispatched += s.prefetchDispatched;
      queue += s.queueLength;
      fallbacks += selection.stats.fallbacks;
      mib += s.residentMiB;
      maxDispatched = std::max(maxDispatched, s.dispatched);
      maxQueue = std::max(maxQueue, s.queueLength);
    }
    // Frames-to-resident over the flight: the pool's histogram minus the warm-up's.
    std::vector<uint64_t> h((*pool)->latencyHistogram().begin(), (*pool)->latencyHistogram().end());
    uint64_t total = 0;
    for (size_t k = 0; k < h.size(); ++k) total += (h[k] -= before[k]);
    const auto percentile = [&](double fraction) {
      const uint64_t target = std::max<uint64_t>(1, uint64_t(std::ceil(fraction * double(total))));
      uint64_t seen = 0;
      for (size_t k = 0; k < h.size(); ++k)
        if ((seen += h[k]) >= target) return double(k);
      return double(h.size() - 1);
    };
    const double frames = kFlightFrames;
    state.counters["lat_p50"] = percentile(0.5);
    state.counters["lat_p90"] = percentile(0.9);
    state.counters["lat_p99"] = percentile(0.99);
    state.counters["lat_max"] = percentile(1.0);
    state.counters["disp_mean"] = dispatched / frames;
    state.counters["disp_max"] = maxDispatched;
    state.counters["pf_share"] = dispatched > 0 ? prefetchDispatched / dispatched : 0.0;
    state.counters["queue_mean"] = queue / frames;
    state.counters["queue_max"] = maxQueue;
    state.counters["fallback_mean"] = fallbacks / frames;
    state.counters["resident_MiB"] = mib / frames;
  }
}

void registerAll() {
  struct Flight {
    const char* name;
    double altitude_m, speed_mps;
  };
  for (const Flight& f :
       {Flight{"alt_1km/speed_1km_s", 1000.0, 1000.0}, Flight{"alt_100m/speed_300m_s", 100.0, 300.0}}) {
    for (bool prefetch : {true, false}) {
      const std::string name = std::string("Streaming/") + f.name + (prefetch ? "/prefetch" : "/no_prefetch");
      benchmark::RegisterBenchmark(name.c_str(), flight, f.altitude_m, f.speed_mps, prefetch)
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

const int kRegistered = (registerAll(), 0);

}  // namespace
}  // namespace globe
