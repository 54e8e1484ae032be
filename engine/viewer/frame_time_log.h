#pragma once
// The viewer's per-frame times: kept for the whole run, summarised on stdout at exit
// ("frames N median_ms X p95_ms Y") and, with --frame-times, written as a CSV. No GPU.
#include "planet/analysis/frame_stats.h"
#include "planet/camera/camera.h"
#include "planet/core/error.h"

#include <cstdint>
#include <string>
#include <vector>

namespace globe {

class FrameTimeLog {
 public:
  // One presented frame: `wall_s` since the run's first frame began, `frame_ms` since the previous
  // frame was presented (the first: since the loop started, so it includes the terrain's warm-up),
  // `path_t_s` the camera path time shown (0 without a path), `pose` the camera (height above the ground).
  void add(double wall_s, double path_t_s, double frame_ms, const FrameStats& stats, const GeodeticPose& pose);

  std::size_t size() const { return rows_.size(); }
  // "frames N median_ms X p95_ms Y" (nearest-rank; 0 when there are no frames).
  std::string summaryLine() const;
  // Header "frame,wall_s,path_t_s,frame_ms,nodes_selected,triangles,gpu_ms,height_m,latitude_deg,
  // longitude_deg,heading_deg,pitch_deg", then one line per frame.
  std::string csv() const;
  // Writes csv() to `path` atomically (planet/core/atomic_file.h).
  Status write(const std::string& path) const;

 private:
  struct Row {
    double wall_s, path_t_s, frame_ms;
    uint32_t nodes;
    uint64_t triangles;
    double gpu_ms;
    GeodeticPose pose;
  };
  std::vector<Row> rows_;
};

}  // namespace globe
