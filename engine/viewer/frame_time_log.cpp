#include "engine/viewer/frame_time_log.h"

#include "planet/analysis/percentile.h"
#include "planet/core/atomic_file.h"

#include <algorithm>
#include <charconv>

namespace globe {

namespace {

// Fixed decimals, independent of the locale.
std::string fixed(double value, int decimals) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  return result.ec == std::errc() ? std::string(buffer, result.ptr) : "0";
}

}  // namespace

void FrameTimeLog::add(double wall_s, double path_t_s, double frame_ms, const FrameStats& stats,
                       const GeodeticPose& pose) {
  rows_.push_back({wall_s, path_t_s, frame_ms, stats.nodes_selected, stats.triangles, stats.gpu_ms, pose});
}

std::string FrameTimeLog::summaryLine() const {
  double median = 0, p95 = 0;
  if (!rows_.empty()) {
    std::vector<double> ms;
    ms.reserve(rows_.size());
    for (const Row& r : rows_) ms.push_back(r.frame_ms);
    std::sort(ms.begin(), ms.end());
    median = nearestRankPercentile(ms, 50);
    p95 = nearestRankPercentile(ms, 95);
  }
  return "frames " + std::to_string(rows_.size()) + " median_ms " + fixed(median, 3) + " p95_ms " + fixed(p95, 3);
}

std::string FrameTimeLog::csv() const {
  std::string out =
      "frame,wall_s,path_t_s,frame_ms,nodes_selected,triangles,gpu_ms,height_m,latitude_deg,longitude_deg,"
      "heading_deg,pitch_deg\n";
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const Row& r = rows_[i];
    out += std::to_string(i) + ',' + fixed(r.wall_s, 6) + ',' + fixed(r.path_t_s, 6) + ',' + fixed(r.frame_ms, 4) +
           ',' + std::to_string(r.nodes) + ',' + std::to_string(r.triangles) + ',' + fixed(r.gpu_ms, 4) + ',' +
           fixed(r.pose.height_m, 4) + ',' + fixed(r.pose.latitude_deg, 7) + ',' + fixed(r.pose.longitude_deg, 7) +
           ',' + fixed(r.pose.heading_deg, 3) + ',' + fixed(r.pose.pitch_deg, 3) + '\n';
  }
  return out;
}

Status FrameTimeLog::write(const std::string& path) const { return writeFileAtomically(path, csv(), "--frame-times"); }

}  // namespace globe
