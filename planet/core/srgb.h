#pragma once
// The sRGB transfer function (IEC 61966-2-1): linear [0, 1] <-> display-encoded [0, 1].
#include <algorithm>
#include <cmath>

namespace globe {

inline double srgbEncode(double linear) {
  double c = std::clamp(std::isfinite(linear) ? linear : 0.0, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

inline double srgbDecode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

}  // namespace globe
