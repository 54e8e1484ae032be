#pragma once
// The benchmark's per-frame metrics as columns (name, unit, how to print them) and their summary
// statistics. One table shared by frames.csv, summary.json, the timeline and the report, so the
// four can't disagree about names or units.
#include "engine/report/bench_report.h"
#include "planet/analysis/percentile.h"

#include <cstdint>
#include <span>
#include <string>

namespace globe {

// A frame is janky when it takes longer than this: 30 frames per second.
inline constexpr double kFrameBudgetMs = 33.3;

enum class MetricKind { Integer, Real };

struct BenchMetric {
  const char* name;         // CSV column and JSON key
  const char* unit;         // for people: "ms", "m", "MiB", "" for counts
  const char* description;  // one line, for the report and docs
  MetricKind kind;
  int decimals;  // fixed decimals in the CSV (0 for integers)
  double (*value)(const BenchFrame&);
};

// Every column of frames.csv after `frame` and `t`, in CSV order.
std::span<const BenchMetric> benchMetrics();
// The metric called `name`; asserts it exists.
const BenchMetric& benchMetric(const char* name);

struct MetricSummary {
  double min = 0;
  double median = 0;  // nearest-rank p50: the lower middle sample when the count is even
  double p95 = 0;
  double p99 = 0;
  double max = 0;
  double mean = 0;
};

// Statistics of one metric over `frames` (non-empty).
MetricSummary summarizeMetric(std::span<const BenchFrame> frames, const BenchMetric& metric);

// Σ max(0, frame_ms − kFrameBudgetMs): how much the run overshot 30 fps, in milliseconds.
double jankMs(std::span<const BenchFrame> frames);
// Frames with frame_ms > kFrameBudgetMs.
uint64_t framesOverBudget(std::span<const BenchFrame> frames);

// `value` with exactly `decimals` digits after the point, independent of the locale; -0 prints as 0.
std::string formatFixed(double value, int decimals);

}  // namespace globe
