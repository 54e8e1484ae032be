#include "engine/report/bench_metrics.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cstring>
#include <vector>

namespace globe {

namespace {

constexpr BenchMetric kMetrics[] = {
    {"altitude_m", "m", "camera height above the ground", MetricKind::Real, 3,
     [](const BenchFrame& f) { return f.altitude_m; }},
    {"frame_ms", "ms", "wall time of the frame", MetricKind::Real, 4,
     [](const BenchFrame& f) { return f.stats.frame_ms; }},
    {"select_ms", "ms", "CPU time of LOD selection", MetricKind::Real, 4,
     [](const BenchFrame& f) { return f.stats.select_ms; }},
    {"gpu_ms", "ms", "GPU time of the frame (timestamp queries)", MetricKind::Real, 4,
     [](const BenchFrame& f) { return f.stats.gpu_ms; }},
    {"nodes_selected", "", "quadtree nodes drawn", MetricKind::Integer, 0,
     [](const BenchFrame& f) { return static_cast<double>(f.stats.nodes_selected); }},
    {"nodes_partial", "", "of those, drawn at half resolution: beyond their own level's range", MetricKind::Integer, 0,
     [](const BenchFrame& f) { return static_cast<double>(f.stats.nodes_partial); }},
    {"triangles", "", "triangles submitted", MetricKind::Integer, 0,
     [](const BenchFrame& f) { return static_cast<double>(f.stats.triangles); }},
    {"draw_calls", "", "draw commands recorded", MetricKind::Integer, 0,
     [](const BenchFrame& f) { return static_cast<double>(f.stats.draw_calls); }},
    {"gen_dispatched", "", "payload generation jobs dispatched this frame", MetricKind::Integer, 0,
     [](const BenchFrame& f) { return static_cast<double>(f.stats.gen_dispatched); }},
    {"gen_in_flight", "", "generation jobs on the GPU, not yet complete", MetricKind::Integer, 0,
     [](const BenchFrame& f) { return static_cast<double>(f.stats.gen_in_flight); }},
    {"gen_completed", "", "generation jobs completed this frame", MetricKind::Integer, 0,
     [](const BenchFrame& f) { return static_cast<double>(f.stats.gen_completed); }},
    {"evicted", "", "payloads evicted this frame", MetricKind::Integer, 0,
     [](const BenchFrame& f) { return static_cast<double>(f.stats.evicted); }},
    {"resident_mib", "MiB", "payload memory resident on the GPU", MetricKind::Real, 3,
     [](const BenchFrame& f) { return f.stats.resident_mib; }},
    // Added after the first schema: appended so column positions stay.
    {"ground_speed_mps", "m/s", "camera speed along the ground (horizontal)", MetricKind::Real, 3,
     [](const BenchFrame& f) { return f.groundSpeed_mps; }},
    {"gpu_terrain_ms", "ms", "of gpu_ms: the node grids", MetricKind::Real, 4,
     [](const BenchFrame& f) { return f.stats.gpu_terrain_ms; }},
    {"gpu_skirts_ms", "ms", "of gpu_ms: the skirts at level changes", MetricKind::Real, 4,
     [](const BenchFrame& f) { return f.stats.gpu_skirts_ms; }},
    {"gpu_sky_ms", "ms", "of gpu_ms: the sky", MetricKind::Real, 4,
     [](const BenchFrame& f) { return f.stats.gpu_sky_ms; }},
    {"gpu_generation_ms", "ms", "GPU time of the generation batches collected this frame", MetricKind::Real, 4,
     [](const BenchFrame& f) { return f.stats.gpu_generation_ms; }},
    {"gpu_shadows_ms", "ms", "of gpu_ms: the shadow maps' depth passes", MetricKind::Real, 4,
     [](const BenchFrame& f) { return f.stats.gpu_shadows_ms; }},
};

}  // namespace

std::span<const BenchMetric> benchMetrics() { return kMetrics; }

const BenchMetric& benchMetric(const char* name) {
  for (const BenchMetric& m : kMetrics) {
    if (std::strcmp(m.name, name) == 0) return m;
  }
  assert(false && "unknown bench metric");
  return kMetrics[0];
}

MetricSummary summarizeMetric(std::span<const BenchFrame> frames, const BenchMetric& metric) {
  assert(!frames.empty());
  std::vector<double> values;
  values.reserve(frames.size());
  double sum = 0;
  for (const BenchFrame& f : frames) {
    values.push_back(metric.value(f));
    sum += values.back();  // in frame order, so the mean is the same bytes every run
  }
  std::sort(values.begin(), values.end());
  MetricSummary s;
  s.min = values.front();
  s.max = values.back();
  s.median = nearestRankPercentile(values, 50);
  s.p95 = nearestRankPercentile(values, 95);
  s.p99 = nearestRankPercentile(values, 99);
  s.mean = sum / static_cast<double>(values.size());
  return s;
}

double jankMs(std::span<const BenchFrame> frames) {
  double sum = 0;
  for (const BenchFrame& f : frames) sum += std::max(0.0, f.stats.frame_ms - kFrameBudgetMs);
  return sum;
}

uint64_t framesOverBudget(std::span<const BenchFrame> frames) {
  return static_cast<uint64_t>(std::count_if(frames.begin(), frames.end(),
                                             [](const BenchFrame& f) { return f.stats.frame_ms > kFrameBudgetMs; }));
}

std::string formatFixed(double value, int decimals) {
  char buffer[400];  // 1e308 in fixed notation plus decimals
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  assert(result.ec == std::errc());
  std::string text(buffer, result.ptr);
  // "-0.000" (negative zero, or a tiny negative rounded away) reads as a real sign; drop it.
  if (!text.empty() && text[0] == '-' && text.find_first_not_of("0.", 1) == std::string::npos) text.erase(0, 1);
  return text;
}

}  // namespace globe
