#pragma once
// The benchmark's report: what `globe bench` leaves in its output directory once the replay is
// done. Plain files a person (report.html, timeline.svg) or a script (frames.csv, summary.json)
// can read; no Vulkan here. The formats are documented in docs/benchmark.md ("Report files").
#include "planet/analysis/frame_stats.h"
#include "planet/core/error.h"

#include <cstdint>
#include <span>
#include <string>

namespace globe {

// One replayed frame.
struct BenchFrame {
  uint64_t frame = 0;          // index in the replay, from 0
  double t_s = 0;              // path time of the frame (seconds)
  double altitude_m = 0;       // camera height above the ground below it (metres)
  double groundSpeed_mps = 0;  // horizontal camera speed since the previous frame (m/s; 0 for the first)
  FrameStats stats;
};

// A key-frame image the caller already wrote into the report directory.
struct BenchKeyFrame {
  double t_s = 0;         // path time the image shows (seconds)
  std::string imageFile;  // PNG file name relative to the report directory, e.g. "frame_t07.png"
  // The encoded PNG, written with the report files (all or none), or empty when the caller already
  // wrote imageFile into the directory.
  std::string png;
};

// Frames from a visible generation request to its payload being resident (PayloadPool's
// latency histogram), over the run's requests.
struct GenerationLatency {
  uint64_t requests = 0;  // requests that became resident
  uint32_t p50_frames = 0;
  uint32_t p95_frames = 0;
  uint32_t p99_frames = 0;
};

// How the run was made, echoed into summary.json and the report so a number can be traced back.
struct BenchRunInfo {
  std::string planetFile;
  std::string pathFile;
  std::string mode;        // "budgeted" or "converged"
  std::string device;      // Vulkan device name
  std::string size;        // "WxH" in pixels
  uint32_t gridCells = 0;  // node grid (cells per node side)
  // The rest of the quality settings that move the figures: "aa none, normal map scale 0, atmosphere sky".
  std::string shading;
  std::string commandLine;
  std::string globeVersion;
  // What else moves the figures (docs/benchmark.md); "" where unknown.
  std::string driver;            // Vulkan driver name and version (VkPhysicalDeviceDriverProperties)
  std::string shaderCache;       // Mesa shader cache: "enabled", "disabled (MESA_SHADER_CACHE_DISABLE=true)", ...
  std::string loadAverageStart;  // /proc/loadavg (1, 5, 15 min) when the run started
  std::string loadAverageEnd;    // and when it ended
  std::string commit;            // git commit the binary was built from, or "unknown"
  std::string dateUtc;           // when the run started, ISO 8601 UTC
  GenerationLatency latency;     // measured during the run
};

struct BenchBaseline;

// Writes DIR/frames.csv, DIR/summary.json, DIR/timeline.svg and DIR/report.html. `dir` must exist
// and hold the key-frame images. Same inputs give the same bytes. Every file is first written in
// full to a temporary beside it and only then renamed into place, all four renames after all four
// writes: on an error no report file is created or replaced (only a failing rename itself, which
// needs the directory to change under us, could leave some files new and some old). Frames must be
// in increasing time with finite values; at least one frame is needed. With a `baseline` (an
// earlier run, bench_baseline.h), summary.json and the report put its numbers beside these.
Status writeBenchReport(const std::string& dir, const BenchRunInfo& info, std::span<const BenchFrame> frames,
                        std::span<const BenchKeyFrame> keyFrames, const BenchBaseline* baseline = nullptr);

}  // namespace globe
