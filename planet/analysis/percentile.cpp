#include "planet/analysis/percentile.h"

#include <algorithm>
#include <cassert>
#include <cstddef>

namespace globe {

double nearestRankPercentile(std::span<const double> sorted, uint32_t percent) {
  assert(!sorted.empty() && percent <= 100);
  // Integer arithmetic: ceil(p * n / 100) exactly, no floating-point rounding at the boundaries.
  const uint64_t n = sorted.size();
  const uint64_t rank = std::max<uint64_t>(1, (uint64_t{percent} * n + 99) / 100);
  return sorted[static_cast<std::size_t>(rank - 1)];
}

}  // namespace globe
