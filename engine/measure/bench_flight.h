#pragma once
// The benchmark flight (docs/benchmark.md): a camera path replayed at a fixed time step through a
// Terrain, each frame's statistics spooled to disk as a row, the key frames read back and encoded.
// `globe bench` parses, reports and prints around it.
#include "engine/render/headless_renderer.h"
#include "engine/render/terrain.h"
#include "engine/report/bench_frame_spool.h"
#include "engine/report/bench_report.h"
#include "planet/model/elevation_model.h"
#include "planet/paths/camera_path.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace globe {

struct BenchFlightPlan {
  const CameraPath* path = nullptr;
  uint64_t frames = 0;  // frame k shows t = start + k / rate_hz
  double rate_hz = 60.0;
  std::vector<double> keyTimes;  // seconds of path time; those outside the path are skipped
  bool converge = false;         // every node the view needs resident before drawing (else budgeted)
};

// What the flight produced besides its rows: the key frames' PNGs (kept in memory, so the caller
// writes them with the report at the end and an interrupted run never leaves new key frames beside
// an earlier run's files), and frame 0's statistics.
struct BenchFlight {
  std::vector<BenchKeyFrame> keys;
  FrameStats firstFrame;
};

// Called after each frame `k` is drawn and its row recorded, before its key frames are read back
// (progress, warnings, clocks).
using BenchFrameDone = std::function<void(uint64_t k)>;

// Flies the plan. Heights are above the drawn mesh, like `globe render --at` and the viewer.
Result<BenchFlight> flyBenchPath(const BenchFlightPlan& plan, const ElevationModel& model, Terrain& terrain,
                                 HeadlessRenderer& renderer, BenchFrameSpool& rows, const BenchFrameDone& done);

// The pool's generation latency in frames (request -> resident): p50, p95, p99.
GenerationLatency generationLatency(const PayloadPool& pool);

}  // namespace globe
