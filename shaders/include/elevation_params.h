// Elevation parameters shared by C++ (planet/model/elevation_model.h) and GLSL (shaders/include/elevation.glsl).
// This file compiles as both: C++ sees namespace globe::gpu and static_asserts, GLSL sees plain
// structs. Layout: identical under std430 and std140 (only double/uint scalars, every struct a
// multiple of 16 bytes), so it can live in a uniform or a storage buffer. Offsets in bytes are in
// the comments; C++ fills it with globe::packElevationParams(PlanetDescription) and uploads the bytes
// as they are. The CPU reference evaluates from this same struct, so both sides read the same
// doubles (frequencies are 1/wavelength computed once, on the CPU).
#ifndef GLOBE_ELEVATION_PARAMS_H
#define GLOBE_ELEVATION_PARAMS_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace globe::gpu {
using uint = std::uint32_t;
#endif

// Most layers a planet can have (the GPU struct is fixed-size).
#define GLOBE_MAX_ELEVATION_LAYERS 8
// ElevationLayerParams.kind values.
#define GLOBE_LAYER_FBM 0u      // sum of amp_i * n_i, in [-sum amp, +sum amp] * noise bound
#define GLOBE_LAYER_RIDGED 1u   // sum of amp_i * (1 - |n_i|)^2: sharp crests, non-negative
#define GLOBE_LAYER_BILLOW 2u   // sum of amp_i * |n_i|: rounded bumps, non-negative
#define GLOBE_LAYER_CRATERS 3u  // sum of amp_i * crater field_i: bowls, rims, ejecta (crater_field.h)
// ElevationLayerParams.modulator value for "not modulated".
#define GLOBE_NO_MODULATOR (-1)

// One layer of octaves (80 bytes).
struct ElevationLayerParams {
  double frequency;             //  0: cycles per metre of the first octave (1 / wavelength)
  double lacunarity;            //  8: frequency multiplier per octave (> 1)
  double gain;                  // 16: amplitude multiplier per octave
  double amplitude_m;           // 24: amplitude of the first octave, metres
  double offset_m;              // 32: constant added to the layer, metres (not modulated)
  double modulation_low_m;      // 40: modulator value (m) at which the mask is 0
  double modulation_inv_range;  // 48: 1 / (high - low), per metre
  double modulation_floor;      // 56: amplitude scale where the mask is 0, in [0, 1]
  uint seed;                    // 64: 32-bit noise seed of octave 0 (octave i: seed + i * 0x9e3779b9)
  uint octaves;                 // 68: number of octaves, >= 1
  uint kind;                    // 72: GLOBE_LAYER_*
  int modulator;                // 76: index of an earlier layer, or GLOBE_NO_MODULATOR
};

// Specialization constants of every kernel that includes elevation.glsl: the planet's structure as
// compile-time constants, so the layer and octave loops unroll into straight-line code (a loop costs
// masked stores of every live value per iteration on lavapipe: the unrolled 12-octave kernel measured
// 1.5x faster, docs/elevation.md). Constant id = GLOBE_ELEVATION_SPEC_* + layer; every value is 32
// bits; the C++ side builds them from ElevationParams (globe::elevationSpecialization), so they can't
// disagree with the parameter block.
#define GLOBE_ELEVATION_SPEC_LAYER_COUNT 0  // layer_count
#define GLOBE_ELEVATION_SPEC_OCTAVES 1      // layers[l].octaves, ids 1..8
#define GLOBE_ELEVATION_SPEC_KIND 9         // layers[l].kind, ids 9..16
#define GLOBE_ELEVATION_SPEC_MODULATOR 17   // layers[l].modulator (int), ids 17..24
#define GLOBE_ELEVATION_SPEC_ELLIPSOID 25   // 1 when polar_radius_m != radius_m (surface on an ellipsoid), else 0
#define GLOBE_ELEVATION_SPEC_COUNT 26

// The whole elevation function (32 + 8 * 80 = 672 bytes).
struct ElevationParams {
  double radius_m;        //  0: sphere radius or equatorial radius a, metres (elevation 0)
  double sea_level_m;     //  8: elevation of the sea surface, metres (the payload kernel places lower samples on it
                          //     with GLOBE_PAYLOAD_SPEC_WATER_SURFACE)
  uint layer_count;       // 16: layers in use, 1 .. GLOBE_MAX_ELEVATION_LAYERS
  uint pad0;              // 20
  double polar_radius_m;  // 24: b = a (1 - flattening), metres; = radius_m on a sphere
  ElevationLayerParams layers[GLOBE_MAX_ELEVATION_LAYERS];  // 32
};

#ifdef __cplusplus
static_assert(sizeof(ElevationLayerParams) == 80);
static_assert(offsetof(ElevationLayerParams, seed) == 64);
static_assert(offsetof(ElevationLayerParams, modulator) == 76);
static_assert(offsetof(ElevationParams, polar_radius_m) == 24);
static_assert(offsetof(ElevationParams, layers) == 32);
static_assert(sizeof(ElevationParams) == 672);
}  // namespace globe::gpu
#endif

#endif  // GLOBE_ELEVATION_PARAMS_H
