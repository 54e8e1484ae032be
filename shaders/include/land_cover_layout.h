// Land cover of a planet: up to 8 classes blended by masks, from a procedural climate. Shared by C++
// (planet/surface/land_cover.h) and GLSL (land_cover.glsl), like colour_ramp_layout.h: C++ sees namespace
// globe::gpu, GLSL plain structs; 32-bit scalars only, every struct a multiple of 16 bytes, so the
// layout is the same under std140 and std430. globe::landCoverMasks (planet/surface/land_cover.cpp)
// is the reference evaluation the shader mirrors:
//   lat   = the unit direction's z (the sine of the geocentric latitude)
//   nT,nM = 3 octaves of gradient noise (lacunarity 2, gain 0.5) at direction * noise_scale, float,
//           seeds seed and seed + 1
//   above = h - sea level (m); base = the planet's first layer's value minus sea level (m)
//   T     = equator_t + (pole_t - equator_t) * lat^2 + temperature_noise_c * nT - lapse * max(above, 0)
//   M     = clamp(moisture_base + moisture_noise * nM - inland_drying * max(base, 0), 0, 1)
//   slope = degrees(acos(cos_slope))
//   w_i   = band(T, class temperature) * band(M, moisture) * band(above, elevation) * band(slope, slope)
// band(x, [lo, hi]) = smoothstep over blend around lo times (1 - smoothstep over blend around hi).
// The weights are normalised (the first class takes what is missing where no rule holds) and packed
// into 8 bytes that sum to exactly 255 (the largest takes the rounding remainder): the masks, two
// RGBA8 words per sample. The ground's albedo is sum(mask_i / 255 * colour_i).
#ifndef GLOBE_LAND_COVER_H
#define GLOBE_LAND_COVER_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace globe::gpu {
using uint = std::uint32_t;
#endif

// Most classes a planet can have: 8 masks of one byte in two RGBA8 words.
#define GLOBE_MAX_LAND_COVER_CLASSES 8

// One class (48 bytes). Unbounded ends of a range are +-1e30.
struct LandCoverClassParams {
  float temperature_min_c;  //  0: mean temperature range, degrees Celsius
  float temperature_max_c;  //  4
  float moisture_min;       //  8: moisture range, 0..1
  float moisture_max;       // 12
  float elevation_min_m;    // 16: height above sea level range, metres
  float elevation_max_m;    // 20
  float slope_min_deg;      // 24: slope range, degrees from horizontal
  float slope_max_deg;      // 28
  float r;                  // 32: linear albedo, the class's mean colour
  float g;                  // 36
  float b;                  // 40
  float pad0;               // 44
};

// The whole land cover (64 + 8 * 48 = 448 bytes). class_count = 0: no land cover (the colour ramp
// colours the ground).
struct LandCoverParams {
  uint class_count;             //  0: classes in use, 0 .. GLOBE_MAX_LAND_COVER_CLASSES
  uint seed;                    //  4: noise seed of the temperature noise (moisture: seed + 1)
  float noise_scale;            //  8: noise lattice units per unit direction (radius / wavelength)
  float equator_temperature_c;  // 12
  float pole_temperature_c;     // 16
  float lapse_rate_c_per_m;     // 20: cooling per metre above sea level
  float temperature_noise_c;    // 24
  float moisture_base;          // 28
  float moisture_noise;         // 32
  float inland_drying_per_m;    // 36: moisture lost per metre the first layer stands above sea level
  float sea_level_m;            // 40
  float temperature_blend_c;    // 44: width of each class's soft temperature edges (> 0)
  float moisture_blend;         // 48
  float elevation_blend_m;      // 52
  float slope_blend_deg;        // 56
  uint pad0;                    // 60
  LandCoverClassParams classes[GLOBE_MAX_LAND_COVER_CLASSES];  // 64
};

#ifdef __cplusplus
static_assert(sizeof(LandCoverClassParams) == 48);
static_assert(offsetof(LandCoverParams, classes) == 64);
static_assert(sizeof(LandCoverParams) == 448);
}  // namespace globe::gpu
#endif

#endif  // GLOBE_LAND_COVER_H
