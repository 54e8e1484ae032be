#pragma once
// Comparing payload surface words (normal.w: albedo and hole mask bytes, payload_surface.glsl)
// between the GPU kernel and the CPU reference.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdlib>

namespace globe::testing {

// Largest difference between the albedo bytes of two surface words (1 = one 8-bit step: the GPU's
// float ramp and the CPU's may round a channel either way).
inline int albedoByteDistance(float gpu, float cpu) {
  const auto a = std::bit_cast<std::uint32_t>(gpu), b = std::bit_cast<std::uint32_t>(cpu);
  int worst = 0;
  for (int k = 0; k < 3; ++k)
    worst = std::max(worst, std::abs(int((a >> (8 * k)) & 0xffu) - int((b >> (8 * k)) & 0xffu)));
  return worst;
}

// The hole mask byte (0..255).
inline int holeByte(float word) { return int(std::bit_cast<std::uint32_t>(word) >> 24); }

}  // namespace globe::testing
