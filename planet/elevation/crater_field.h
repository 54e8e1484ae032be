#pragma once
// Impact craters as a layer kind ("craters"): one octave is a field of bowl-shaped craters with
// raised rims and ejecta, one candidate crater per cell of the 3-D lattice (in lattice units, like
// gradientNoise). Octave i has cells lacunarity^i times smaller, so the number of craters per unit
// area grows as size^-2: the cumulative size–frequency distribution N(>D) ∝ D^-2 of lunar craters
// in equilibrium [Melosh 1989, §10.2]; depth scales with the octave's amplitude (gain 1/lacunarity
// keeps depth ∝ diameter, depth/diameter ≈ 0.2 for simple craters [Pike 1977]).
//
// Per cell, a 32-bit hash (hashMix32 of the lattice point hash) decides: occupied (1 bit, half the
// cells), the radius class k (2 bits: radius sqrt(1/8), 1/4, sqrt(1/32), 1/8 cells, so 1/R^2 is an
// exact power of two) and the centre's offset in the cell (3 x 8 bits, exact multiples of 1/256).
// A crater reaches r = sqrt(1.5) R <= 0.433 cells, so the 2x2x2 cells at floor(q - 1/2) hold every
// crater that can touch q. The profile uses only s = r^2 / R^2 (no square root, no division):
//   bowl   s < 1:    f = -1 + (1 + H) s^2          (f(0) = -1, f(1) = H: the rim crest)
//   ejecta s < 1.5:  f = H t^3, t = 2 (1.5 - s)    (continuous at the crest, flat where it ends)
// with rim height H = 1/4 of the depth. Craters in one octave combine as the deepest bowl plus the
// sum of the raised parts (rims, ejecta): overlapping bowls don't dig deeper than the deepest (the
// younger crater erases the floor it lands on), and the field stays continuous. Only + - * and floor: the GLSL
// mirror in shaders/include/elevation_real.glsl gives bit-identical doubles. Change both or neither.
#include <algorithm>
#include <cstdint>

#include "planet/core/gradient_noise.h"

namespace globe {

inline constexpr double kCraterRimHeight = 0.25;  // H, as a fraction of the crater's depth
// 1 / R^2 per radius class, cells^-2, and the depth of each class relative to the largest.
inline constexpr double kCraterInverseRadiusSquared[4] = {8.0, 16.0, 32.0, 64.0};
inline constexpr double kCraterDepthScale[4] = {1.0, 0.75, 0.5, 0.375};
// Bounds of one octave, in units of the octave's amplitude: the deepest floor, and the raised parts
// of 8 overlapping craters at most.
inline constexpr double kCraterFieldMin = -1.0;
inline constexpr double kCraterFieldMax = 8.0 * kCraterRimHeight;
// Upper bound of |d field / d q| per lattice unit: one crater's steepest wall is 5 / R * depth
// scale <= 15 (the bowl at s = 1); the deepest bowl plus 8 raised parts.
inline constexpr double kCraterFieldSlopeBound = 135.0;

// The crater profile f(s) for one crater, s = r^2 / R^2 (0 outside the ejecta).
template <class Real>
inline Real craterProfile(Real s) {
  if (s < Real(1)) return Real(-1) + (Real(1) + Real(kCraterRimHeight)) * (s * s);
  if (s < Real(1.5)) {
    const Real t = Real(2) * (Real(1.5) - s);
    return Real(kCraterRimHeight) * (t * t * t);
  }
  return Real(0);
}

// One crater cell's contribution at offset (x, y, z) from the cell's lower corner, in cells.
template <class Real>
inline Real craterCell(std::uint32_t hash, Real x, Real y, Real z) {
  const std::uint32_t h = hashMix32(hash);
  if ((h & 1U) == 0U) return Real(0);  // half the cells hold no crater
  const std::uint32_t k = (h >> 1) & 3U;
  const Real cx = Real((h >> 8) & 255U) * Real(1.0 / 256.0);
  const Real cy = Real((h >> 16) & 255U) * Real(1.0 / 256.0);
  const Real cz = Real(h >> 24) * Real(1.0 / 256.0);
  const Real ox = x - cx;
  const Real oy = y - cy;
  const Real oz = z - cz;
  const Real s = (ox * ox + oy * oy + oz * oz) * Real(kCraterInverseRadiusSquared[k]);
  return Real(kCraterDepthScale[k]) * craterProfile(s);
}

// The crater field at (x, y, z) in lattice units for one 32-bit seed, in units of the octave's
// depth: in [kCraterFieldMin, kCraterFieldMax].
template <class Real>
inline Real craterField(Real x, Real y, Real z, std::uint32_t seed) {
  const Real fx = std::floor(x - Real(0.5));
  const Real fy = std::floor(y - Real(0.5));
  const Real fz = std::floor(z - Real(0.5));
  const auto ix = static_cast<std::int64_t>(fx);
  const auto iy = static_cast<std::int64_t>(fy);
  const auto iz = static_cast<std::int64_t>(fz);
  const Real x0 = x - fx;  // offsets from the lower cell's corner, in [0.5, 1.5)
  const Real y0 = y - fy;
  const Real z0 = z - fz;
  Real deepest = Real(0);
  Real raised = Real(0);
  for (int c = 0; c < 8; ++c) {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
    const std::uint32_t hash =
        latticeCornerHash(latticeWordX(ix + dx), latticeWordY(iy + dy), latticeWordZ(iz + dz), seed);
    const Real crater = craterCell(hash, x0 - Real(dx), y0 - Real(dy), z0 - Real(dz));
    deepest = std::min(deepest, crater);
    raised = raised + std::max(crater, Real(0));
  }
  return deepest + raised;
}

}  // namespace globe
