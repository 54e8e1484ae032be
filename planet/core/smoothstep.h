#pragma once
// The cubic smoothstep on [0, 1]: the feather the mosaics fade their borders with.
#include <algorithm>

namespace globe {

inline double smoothstep01(double x) {
  const double t = std::clamp(x, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace globe
