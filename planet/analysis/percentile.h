#pragma once
// Percentiles of measured samples (frame times, screen errors), one definition for every report.
#include <cstdint>
#include <span>

namespace globe {

// Nearest-rank percentile of ascending `sorted` (non-empty): the value at 1-based rank
// ceil(percent / 100 * n), at least rank 1. Always one of the samples; p100 is the maximum.
double nearestRankPercentile(std::span<const double> sorted, uint32_t percent);

}  // namespace globe
