#pragma once
// 3-D gradient noise ([Perlin 2002], "Improving Noise": quintic fade, 12 edge gradients) with an
// integer hash of the lattice coordinates instead of a permutation table. The table lookups bound
// the kernel on lavapipe; the hash was 2.7x faster there (docs/elevation.md, "GPU compute path").
//
// The same function is written in GLSL in shaders/include/elevation.glsl and must give bit-identical
// doubles: only + - * , floor and integer operations are used, in the order written here (the build
// uses -ffp-contract=off, the shader marks the arithmetic `precise`). Change both or neither.
//
// Range: |noise| <= kGradientNoiseBound for every input (the exact supremum over all gradient
// assignments is 1.03635, found by search over the cell; tests/planet/elevation_noise_test.cpp).
#include <cmath>
#include <cstdint>

namespace globe {

// Upper bound of |gradientNoise| (dimensionless). Used by the conservative elevation bounds.
inline constexpr double kGradientNoiseBound = 1.04;

// 32-bit avalanche ("lowbias32" [Wellons 2018]): every input bit flips each output bit
// with probability ~1/2. Derives the layer seeds (not per sample). 32-bit on purpose: 64-bit
// multiplies are emulated on most GPUs and in lavapipe's AVX2 code.
constexpr std::uint32_t hashMix32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// Folds a 64-bit lattice coordinate into a 32-bit key: identity for |i| < 2^31 (the low word),
// the high word mixed in for larger or negative coordinates so distinct words don't alias simply.
constexpr std::uint32_t latticeKey(std::int64_t i) {
  const auto u = static_cast<std::uint64_t>(i);
  const auto lo = static_cast<std::uint32_t>(u & 0xffffffffULL);
  const auto hi = static_cast<std::uint32_t>(u >> 32);
  return lo ^ (hi * 0x9e3779b9U);
}

// Lattice point hash, two steps so a cell's 8 corners share work: each axis's key times its own odd
// constant (a "word", 6 per cell), then per corner the xor of the three words and the seed, folded
// (x ^= x >> 16) and multiplied once. The gradient index is the product's top 4 bits, which depend
// on every bit of the folded word. 14 32-bit multiplies per cell instead of the 28 of a nested
// avalanche hash (hashMix32 per axis): on lavapipe the hash was the larger part of the noise
// (docs/elevation.md, "GPU compute path").
constexpr std::uint32_t latticeWordX(std::int64_t i) { return latticeKey(i) * 0x9e3779b1U; }
constexpr std::uint32_t latticeWordY(std::int64_t i) { return latticeKey(i) * 0x85ebca77U; }
constexpr std::uint32_t latticeWordZ(std::int64_t i) { return latticeKey(i) * 0xc2b2ae3dU; }
constexpr std::uint32_t latticeCornerHash(std::uint32_t wx, std::uint32_t wy, std::uint32_t wz, std::uint32_t seed) {
  std::uint32_t x = wx ^ wy ^ wz ^ seed;
  x ^= x >> 16;
  return x * 0x045d9f3bU;
}
// The hash of lattice point (x, y, z) for `seed`: what gradientNoise uses at each corner.
constexpr std::uint32_t latticePointHash(std::int64_t x, std::int64_t y, std::int64_t z, std::uint32_t seed) {
  return latticeCornerHash(latticeWordX(x), latticeWordY(y), latticeWordZ(z), seed);
}

// Perlin's 16 gradients (the 12 cube edges, four of them twice), indexed by the hash's top 4 bits.
inline constexpr signed char kNoiseGradients[16][3] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {0, -1, 1}, {-1, 1, 0}, {0, -1, -1}};

// Gradient g(h) . (x, y, z). A table and products instead of Perlin's branches (the branches on
// random hash bits mispredict and cost 2x on the CPU). Exact: each product is +-x, +-y, +-z or +-0,
// so the value equals the shader's select form (+-u) + (+-v) except for the sign of a zero.
template <class Real>
inline Real gradientDot(std::uint32_t hash, Real x, Real y, Real z) {
  const signed char* g = kNoiseGradients[hash >> 28];
  return static_cast<Real>(g[0]) * x + static_cast<Real>(g[1]) * y + static_cast<Real>(g[2]) * z;
}

// Quintic fade 6t^5 - 15t^4 + 10t^3, written in this Horner order on both sides.
template <class Real>
inline Real noiseFade(Real t) {
  return t * t * t * (t * (t * Real(6) - Real(15)) + Real(10));
}

template <class Real>
inline Real noiseLerp(Real a, Real b, Real t) {
  return a + t * (b - a);
}

// Gradient noise at (x, y, z) in lattice units (cycles), for one 32-bit seed. Continuous with
// continuous first and second derivatives; zero on the lattice points. Coordinates must satisfy
// |x|, |y|, |z| < 2^62 (the planet validator keeps them below 2^40); Real is double (the reference)
// or float (only to measure float's error).
template <class Real>
inline Real gradientNoise(Real x, Real y, Real z, std::uint32_t seed) {
  const Real fx = std::floor(x);
  const Real fy = std::floor(y);
  const Real fz = std::floor(z);
  const auto ix = static_cast<std::int64_t>(fx);
  const auto iy = static_cast<std::int64_t>(fy);
  const auto iz = static_cast<std::int64_t>(fz);
  // Offsets from the cell's lower corner, in [0, 1].
  const Real x0 = x - fx;
  const Real y0 = y - fy;
  const Real z0 = z - fz;
  const Real x1 = x0 - Real(1);
  const Real y1 = y0 - Real(1);
  const Real z1 = z0 - Real(1);

  const std::uint32_t wx0 = latticeWordX(ix);
  const std::uint32_t wx1 = latticeWordX(ix + 1);
  const std::uint32_t wy0 = latticeWordY(iy);
  const std::uint32_t wy1 = latticeWordY(iy + 1);
  const std::uint32_t wz0 = latticeWordZ(iz);
  const std::uint32_t wz1 = latticeWordZ(iz + 1);

  const Real g000 = gradientDot(latticeCornerHash(wx0, wy0, wz0, seed), x0, y0, z0);
  const Real g100 = gradientDot(latticeCornerHash(wx1, wy0, wz0, seed), x1, y0, z0);
  const Real g010 = gradientDot(latticeCornerHash(wx0, wy1, wz0, seed), x0, y1, z0);
  const Real g110 = gradientDot(latticeCornerHash(wx1, wy1, wz0, seed), x1, y1, z0);
  const Real g001 = gradientDot(latticeCornerHash(wx0, wy0, wz1, seed), x0, y0, z1);
  const Real g101 = gradientDot(latticeCornerHash(wx1, wy0, wz1, seed), x1, y0, z1);
  const Real g011 = gradientDot(latticeCornerHash(wx0, wy1, wz1, seed), x0, y1, z1);
  const Real g111 = gradientDot(latticeCornerHash(wx1, wy1, wz1, seed), x1, y1, z1);

  const Real u = noiseFade(x0);
  const Real v = noiseFade(y0);
  const Real w = noiseFade(z0);
  const Real a00 = noiseLerp(g000, g100, u);
  const Real a10 = noiseLerp(g010, g110, u);
  const Real a01 = noiseLerp(g001, g101, u);
  const Real a11 = noiseLerp(g011, g111, u);
  const Real b0 = noiseLerp(a00, a10, v);
  const Real b1 = noiseLerp(a01, a11, v);
  return noiseLerp(b0, b1, w);
}

}  // namespace globe
