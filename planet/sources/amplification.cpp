#include "planet/sources/amplification.h"

#include "planet/core/gradient_noise.h"

#include <algorithm>
#include <cmath>

namespace globe {

int amplificationOctaves(double pixel_m) {
  const double ratio = pixel_m / kAmplificationFinestWavelength_m;
  const int octaves = ratio > 1.0 ? int(std::ceil(std::log2(ratio))) : 1;
  return std::clamp(octaves, 1, kAmplificationMaxOctaves);
}

double amplificationDetail_m(const glm::dvec3& unitDirection, double radius_m, double pixel_m, int octaves,
                             std::uint32_t seed, double relief_m) {
  if (relief_m <= 0.0 || octaves <= 0) return 0.0;
  const glm::dvec3 p = unitDirection * radius_m;
  double frequency = 1.0 / pixel_m, amplitude = kAmplificationGain * relief_m, sum = 0.0;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * gradientNoise(p.x * frequency, p.y * frequency, p.z * frequency, seed);
    frequency *= 2.0;
    amplitude *= 0.5;
    seed += 0x9e3779b9U;
  }
  return sum;
}

double amplificationBoundPerRelief(int octaves) {
  return kAmplificationGain * kGradientNoiseBound * (2.0 - std::ldexp(1.0, 1 - octaves));
}

}  // namespace globe
