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
  uint64_t frame = 0;     // index in the replay, from 0
  double t_s = 0;         // path time of the frame (seconds)
  double altitude_m = 0;  // camera height above the ground below it (metres)
  FrameStats stats;
};

// A key-frame image the caller already wrote into the report directory.
struct BenchKeyFrame {
  double t_s = 0;         // path time the image shows (seconds)
  std::string imageFile;  // PNG file name relative to the report directory, e.g. "frame_t07.png"
};

// How the run was made, echoed into summary.json and the report so a number can be traced back.
struct BenchRunInfo {
  std::string planetFile;
  std::string pathFile;
  std::string mode;        // "budgeted" or "converged"
  std::string device;      // Vulkan device name
  std::string size;        // "WxH" in pixels
  uint32_t gridCells = 0;  // node grid (cells per node side)
  std::string commandLine;
  std::string globeVersion;
};

// Writes DIR/frames.csv, DIR/summary.json, DIR/timeline.svg and DIR/report.html. `dir` must exist
// and hold the key-frame images. Same inputs give the same bytes. Every file is first written in
// full to a temporary beside it and only then renamed into place, all four renames after all four
// writes: on an error no report file is created or replaced (only a failing rename itself, which
// needs the directory to change under us, could leave some files new and some old). Frames must be
// in increasing time with finite values; at least one frame is needed.
Status writeBenchReport(const std::string& dir, const BenchRunInfo& info, std::span<const BenchFrame> frames,
                        std::span<const BenchKeyFrame> keyFrames);

}  // namespace globe
