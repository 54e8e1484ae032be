#pragma once
// The range check of every planet-file number: NaN and ±Inf fail whatever the bounds.
#include <cmath>

namespace globe {

// True when `v` is finite and within [lo, hi].
inline bool inRange(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

}  // namespace globe
