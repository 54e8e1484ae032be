#pragma once
// The one 64-bit integer hash: the splitmix64 finaliser [Steele 2014], for hash tables
// over keys that differ in few bits (node keys). The 32-bit noise lattice hash is separate on
// purpose: it is mirrored bit for bit in the shaders (planet/elevation/gradient_noise.h).
#include <cstdint>

namespace globe {

constexpr std::uint64_t mix64(std::uint64_t key) {
  std::uint64_t z = key + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace globe
