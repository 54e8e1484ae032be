#pragma once
// `globe bench --baseline DIR`: an earlier run's summary.json, read so the report can put its
// numbers beside this run's with ratios. Only what the comparison needs is kept.
#include "engine/report/bench_metrics.h"
#include "planet/core/error.h"

#include <string>
#include <utility>
#include <vector>

namespace globe {

struct BenchBaseline {
  std::string file;    // the summary.json read (DIR/summary.json)
  std::string commit;  // "" when the earlier run did not record it
  std::string dateUtc;
  std::string device;
  std::string mode;
  double jank_ms = 0;
  uint64_t framesOverBudget = 0;
  // The metrics present in both the file and this build's table, in the table's order.
  std::vector<std::pair<std::string, MetricSummary>> metrics;

  // The baseline's statistics of `name`, or null when it has none.
  const MetricSummary* metric(const std::string& name) const;
};

// Reads DIR/summary.json. Errors name the file and the offending key: unreadable, not JSON, not a
// globe-bench-summary, a metric whose statistics are not numbers, frame_ms missing.
Result<BenchBaseline> readBenchBaseline(const std::string& dir);

}  // namespace globe
