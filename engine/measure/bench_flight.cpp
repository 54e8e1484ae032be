#include "engine/measure/bench_flight.h"

#include "engine/io/image_io.h"
#include "engine/render/render_output.h"
#include "planet/camera/camera_orientation.h"

#include <cmath>
#include <cstdio>

namespace globe {

namespace {

// Horizontal speed between two camera positions `dt_s` apart (metres per second), across the
// local vertical `up` (unit; the ellipsoid's normal below the camera).
double groundSpeed_mps(const glm::dvec3& from_m, const glm::dvec3& to_m, const glm::dvec3& up, double dt_s) {
  const glm::dvec3 step = to_m - from_m;
  return glm::length(step - glm::dot(step, up) * up) / dt_s;
}

// The key frames due at frame `k` (the frame nearest to each key time), read back and encoded.
Status keepKeyFrames(const BenchFlightPlan& plan, uint64_t k, HeadlessRenderer& renderer, const Camera& camera,
                     std::vector<BenchKeyFrame>& keys) {
  const CameraPath& path = *plan.path;
  for (double kt : plan.keyTimes) {
    if (kt < path.startTime_s() || kt > path.endTime_s()) continue;
    if (std::llround((kt - path.startTime_s()) * plan.rate_hz) != int64_t(k)) continue;
    char name[64];
    std::snprintf(name, sizeof(name), "keyframe_%05.2fs.png", kt);
    Result<std::string> png = encodePng(toImage(renderer.readback(), camera));
    if (!png) return png.error();
    keys.push_back({kt, name, std::move(*png)});
  }
  return Ok{};
}

}  // namespace

Result<BenchFlight> flyBenchPath(const BenchFlightPlan& plan, const ElevationModel& model, Terrain& terrain,
                                 HeadlessRenderer& renderer, BenchFrameSpool& rows, const BenchFrameDone& done) {
  const CameraPath& path = *plan.path;
  const VkExtent2D extent = renderer.extent();
  const double aspect = double(extent.width) / double(extent.height);
  GroundRadiusFn ground = [&](const glm::dvec3& d) { return terrain.cameraGroundRadius(d); };
  BenchFlight flight;
  glm::dvec3 previousPosition_m(0.0);
  for (uint64_t k = 0; k < plan.frames; ++k) {
    double t = path.startTime_s() + double(k) / plan.rate_hz;
    Camera camera = path.cameraAt(t, model.radius_m(), aspect, ground, model.shape());
    FrameStats stats = renderer.renderFrame(terrain, camera, plan.converge);
    const glm::dvec3 below =
        model.shape().isSphere() ? glm::normalize(camera.position_m) : model.shape().normalBelow(camera.position_m);
    const double altitude = poseFromCamera(camera, ground(below), model.shape()).height_m;
    const double speed =
        k > 0 ? groundSpeed_mps(previousPosition_m, camera.position_m, below, 1.0 / plan.rate_hz) : 0.0;
    previousPosition_m = camera.position_m;
    if (auto s = rows.append({k, t, altitude, speed, stats}); !s) return s.error();
    if (k == 0) flight.firstFrame = stats;
    if (done) done(k);  // before the key frame's readback: frame 0's clock is the frame's own
    if (auto s = keepKeyFrames(plan, k, renderer, camera, flight.keys); !s) return s.error();
  }
  return flight;
}

GenerationLatency generationLatency(const PayloadPool& pool) {
  GenerationLatency latency;
  for (uint64_t count : pool.latencyHistogram()) latency.requests += count;
  if (latency.requests == 0) return latency;
  latency.p50_frames = pool.latencyPercentile(0.50);
  latency.p95_frames = pool.latencyPercentile(0.95);
  latency.p99_frames = pool.latencyPercentile(0.99);
  return latency;
}

}  // namespace globe
