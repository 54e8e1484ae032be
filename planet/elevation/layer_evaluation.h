#pragma once
// The procedural layers' evaluation on the CPU: double precision, deterministic, no fast-math, from the
// packed gpu::ElevationParams the shaders read (shaders/include/elevation_params.h). The GPU mirror
// (shaders/include/elevation.glsl) reproduces it to <= 1e-6 m; the operation order is part of that
// contract (-ffp-contract=off here, `precise` there).
//
// For a unit direction d:
//   p = d * radius_m                                    (metres, the point on the sphere)
//   for each layer l:  sum = sum_i amp_i * t(noise(p * freq_i, seed_i))
//                      sum *= floor + (1 - floor) * smoothstep((value[mod] - low) / (high - low))
//                      value[l] = sum + offset_m;   elevation += value[l]
// with t(n) = n (fbm), (1 - |n|)^2 (ridged), |n| (billow), a crater field (craters);
// freq_{i+1} = freq_i * lacunarity, amp_{i+1} = amp_i * gain, seed_{i+1} = seed_i + 0x9e3779b9 (mod 2^32).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "planet/core/gradient_noise.h"
#include "planet/elevation/crater_field.h"
#include "shaders/include/elevation_params.h"

namespace globe {

// The 32-bit noise seed of a layer, derived from the planet seed and the layer's index.
std::uint32_t layerSeed(std::uint64_t planet_seed, int layer_index);

// The specialization constants every elevation kernel is built with (value i = constant id i, see
// GLOBE_ELEVATION_SPEC_* in elevation_params.h): layer count, then per layer slot the octave count,
// kind and modulator (int bits) of `params`.
using ElevationSpecialization = std::array<std::uint32_t, GLOBE_ELEVATION_SPEC_COUNT>;
ElevationSpecialization elevationSpecialization(const gpu::ElevationParams& params);

// An octave's noise value shaped by the layer kind: n (fbm), (1 - |n|)^2 (ridged), |n| (billow).
template <class Real>
Real shapedNoise(gpu::uint kind, Real n) {
  if (kind == GLOBE_LAYER_RIDGED) {
    const Real c = Real(1) - std::abs(n);
    return c * c;
  }
  if (kind == GLOBE_LAYER_BILLOW) return std::abs(n);
  return n;
}

// The scale a modulated layer's octave sum is multiplied by: floor + (1 - floor) * smoothstep of its
// modulator's value (values[] holds the earlier layers' values); 1 for a layer without modulator.
template <class Real>
Real modulationScale(const gpu::ElevationLayerParams& layer, const Real* values) {
  if (layer.modulator < 0) return Real(1);
  const Real low = static_cast<Real>(layer.modulation_low_m);
  const Real inv_range = static_cast<Real>(layer.modulation_inv_range);
  const Real floor_scale = static_cast<Real>(layer.modulation_floor);
  Real m = (values[layer.modulator] - low) * inv_range;
  m = std::min(std::max(m, Real(0)), Real(1));
  const Real s = m * m * (Real(3) - Real(2) * m);
  return floor_scale + (Real(1) - floor_scale) * s;
}

// A layer's octave sum at the point (px, py, pz) (metres), before modulation and offset.
template <class Real>
Real octaveSum(const gpu::ElevationLayerParams& layer, gpu::uint octaves, Real px, Real py, Real pz) {
  const Real lacunarity = static_cast<Real>(layer.lacunarity);
  const Real gain = static_cast<Real>(layer.gain);
  Real frequency = static_cast<Real>(layer.frequency);
  Real amplitude = static_cast<Real>(layer.amplitude_m);
  std::uint32_t seed = layer.seed;
  Real sum = Real(0);
  for (gpu::uint o = 0; o < octaves; ++o) {
    Real t;
    if (layer.kind == GLOBE_LAYER_CRATERS) {
      t = craterField(px * frequency, py * frequency, pz * frequency, seed);
    } else {
      t = shapedNoise(layer.kind, gradientNoise(px * frequency, py * frequency, pz * frequency, seed));
    }
    sum = sum + amplitude * t;
    frequency = frequency * lacunarity;
    amplitude = amplitude * gain;
    seed = seed + 0x9e3779b9U;
  }
  return sum;
}

// The elevation function. Mirrored statement by statement in shaders/include/elevation.glsl:
// keep the operation order identical (no FMA contraction: -ffp-contract=off / `precise`).
template <class Real>
Real evaluateElevation(const gpu::ElevationParams& p, Real dx, Real dy, Real dz) {
  const Real radius = static_cast<Real>(p.radius_m);
  const Real px = dx * radius;
  const Real py = dy * radius;
  const Real pz = dz * radius;
  Real values[GLOBE_MAX_ELEVATION_LAYERS] = {};
  Real total = Real(0);
  for (gpu::uint l = 0; l < p.layer_count; ++l) {
    const gpu::ElevationLayerParams& layer = p.layers[l];
    // The modulation scale comes first (its modulator is an earlier layer): where it is exactly 0
    // the octaves are skipped. Same value as summing them: sum * 0 is +-0, and +-0 + offset equals
    // 0 + offset for every offset (-0 + +0 = +0), so this is bit-identical to always summing. It
    // saves the mountains' octaves on the ~70 % of earthlike below its 200 m mask threshold (the
    // GPU skips only when all lanes of a subgroup do, which coherent payload samples mostly do).
    const Real scale = modulationScale(layer, values);
    Real sum = octaveSum(layer, scale == Real(0) ? 0U : layer.octaves, px, py, pz);
    if (layer.modulator >= 0) sum = sum * scale;
    const Real value = sum + static_cast<Real>(layer.offset_m);
    values[l] = value;
    total = total + value;
  }
  return total;
}

}  // namespace globe
