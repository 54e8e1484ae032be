// GLSL mirror of the CPU elevation reference (planet/core/gradient_noise.h, planet/model/elevation_model.cpp). Every
// statement follows the C++ in the same order, in double, with `precise` so nothing is contracted
// into an FMA or reassociated: the results must match the CPU to <= 1e-6 m (in practice bit-exact).
// Change both or neither; the golden table in tests/planet/elevation_model_test.cpp notices changes.
//
// Use (GLSL 450, Vulkan; needs shaderFloat64 and shaderInt64):
//   #extension GL_GOOGLE_include_directive : require
//   #extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
//   #include "include/elevation_params.h"
//   layout(std430, set = 0, binding = 0) readonly buffer Elevation { ElevationParams elevation; };
//   #define GLOBE_ELEVATION_PARAMS elevation      // any l-value of type ElevationParams (UBO or SSBO)
//   #include "include/elevation.glsl"
//   ... double h = globeElevation(unit_direction);  dvec3 p = globeSurfacePosition(unit_direction);
// and create the pipeline with the specialization constants of globe::elevationSpecialization(params)
// (ids GLOBE_ELEVATION_SPEC_*): the planet's layer structure is compiled in, its numbers stay in
// the parameter block.
#ifndef GLOBE_ELEVATION_GLSL
#define GLOBE_ELEVATION_GLSL

#include "elevation_params.h"

#ifndef GLOBE_ELEVATION_PARAMS
#error "define GLOBE_ELEVATION_PARAMS (an ElevationParams l-value) before including elevation.glsl"
#endif

#extension GL_EXT_control_flow_attributes : require

// The planet's structure (see elevation_params.h). The defaults are never used: every pipeline
// specializes them.
layout(constant_id = GLOBE_ELEVATION_SPEC_LAYER_COUNT) const uint kGlobeLayerCount = 1u;
layout(constant_id = GLOBE_ELEVATION_SPEC_OCTAVES + 0) const uint kGlobeOctaves0 = 1u;
layout(constant_id = GLOBE_ELEVATION_SPEC_OCTAVES + 1) const uint kGlobeOctaves1 = 1u;
layout(constant_id = GLOBE_ELEVATION_SPEC_OCTAVES + 2) const uint kGlobeOctaves2 = 1u;
layout(constant_id = GLOBE_ELEVATION_SPEC_OCTAVES + 3) const uint kGlobeOctaves3 = 1u;
layout(constant_id = GLOBE_ELEVATION_SPEC_OCTAVES + 4) const uint kGlobeOctaves4 = 1u;
layout(constant_id = GLOBE_ELEVATION_SPEC_OCTAVES + 5) const uint kGlobeOctaves5 = 1u;
layout(constant_id = GLOBE_ELEVATION_SPEC_OCTAVES + 6) const uint kGlobeOctaves6 = 1u;
layout(constant_id = GLOBE_ELEVATION_SPEC_OCTAVES + 7) const uint kGlobeOctaves7 = 1u;
layout(constant_id = GLOBE_ELEVATION_SPEC_KIND + 0) const uint kGlobeKind0 = 0u;
layout(constant_id = GLOBE_ELEVATION_SPEC_KIND + 1) const uint kGlobeKind1 = 0u;
layout(constant_id = GLOBE_ELEVATION_SPEC_KIND + 2) const uint kGlobeKind2 = 0u;
layout(constant_id = GLOBE_ELEVATION_SPEC_KIND + 3) const uint kGlobeKind3 = 0u;
layout(constant_id = GLOBE_ELEVATION_SPEC_KIND + 4) const uint kGlobeKind4 = 0u;
layout(constant_id = GLOBE_ELEVATION_SPEC_KIND + 5) const uint kGlobeKind5 = 0u;
layout(constant_id = GLOBE_ELEVATION_SPEC_KIND + 6) const uint kGlobeKind6 = 0u;
layout(constant_id = GLOBE_ELEVATION_SPEC_KIND + 7) const uint kGlobeKind7 = 0u;
layout(constant_id = GLOBE_ELEVATION_SPEC_MODULATOR + 0) const int kGlobeModulator0 = -1;
layout(constant_id = GLOBE_ELEVATION_SPEC_MODULATOR + 1) const int kGlobeModulator1 = -1;
layout(constant_id = GLOBE_ELEVATION_SPEC_MODULATOR + 2) const int kGlobeModulator2 = -1;
layout(constant_id = GLOBE_ELEVATION_SPEC_MODULATOR + 3) const int kGlobeModulator3 = -1;
layout(constant_id = GLOBE_ELEVATION_SPEC_MODULATOR + 4) const int kGlobeModulator4 = -1;
layout(constant_id = GLOBE_ELEVATION_SPEC_MODULATOR + 5) const int kGlobeModulator5 = -1;
layout(constant_id = GLOBE_ELEVATION_SPEC_MODULATOR + 6) const int kGlobeModulator6 = -1;
layout(constant_id = GLOBE_ELEVATION_SPEC_MODULATOR + 7) const int kGlobeModulator7 = -1;
layout(constant_id = GLOBE_ELEVATION_SPEC_ELLIPSOID) const uint kGlobeEllipsoid = 0u;
// Per-layer lookups (a spec-constant array can't be a global const); constant-folded for a literal l.
uint globeLayerOctaves(uint l) {
  return l == 0u ? kGlobeOctaves0 : l == 1u ? kGlobeOctaves1 : l == 2u ? kGlobeOctaves2 : l == 3u ? kGlobeOctaves3
       : l == 4u ? kGlobeOctaves4 : l == 5u ? kGlobeOctaves5 : l == 6u ? kGlobeOctaves6 : kGlobeOctaves7;
}
uint globeLayerKind(uint l) {
  return l == 0u ? kGlobeKind0 : l == 1u ? kGlobeKind1 : l == 2u ? kGlobeKind2 : l == 3u ? kGlobeKind3
       : l == 4u ? kGlobeKind4 : l == 5u ? kGlobeKind5 : l == 6u ? kGlobeKind6 : kGlobeKind7;
}
int globeLayerModulator(uint l) {
  return l == 0u ? kGlobeModulator0 : l == 1u ? kGlobeModulator1 : l == 2u ? kGlobeModulator2
       : l == 3u ? kGlobeModulator3 : l == 4u ? kGlobeModulator4 : l == 5u ? kGlobeModulator5
       : l == 6u ? kGlobeModulator6 : kGlobeModulator7;
}

// = globe::hashMix32 ("lowbias32").
uint globeHashMix32(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// = globe::latticeKey: low word, high word times the golden ratio constant.
uint globeLatticeKey(int64_t i) {
  uint64_t u = uint64_t(i);
  uint lo = uint(u & 0xffffffffUL);
  uint hi = uint(u >> 32);
  return lo ^ (hi * 0x9e3779b9u);
}

// = globe::latticeCornerHash.
uint globeLatticeCornerHash(uint wx, uint wy, uint wz, uint seed) {
  uint x = wx ^ wy ^ wz ^ seed;
  x ^= x >> 16;
  return x * 0x045d9f3bu;
}

#define GLOBE_REAL double
#define GLOBE_REAL3 dvec3
#define GLOBE_FN(name) name
#include "elevation_real.glsl"
#undef GLOBE_REAL
#undef GLOBE_REAL3
#undef GLOBE_FN

// The same evaluation entirely in float (= globe::ElevationModel::elevationFloat_m), as
// globeElevationFloat(vec3): only to measure what double buys (the float generation variant of
// globe trade). Define GLOBE_ELEVATION_FLOAT before including this file to get it.
#ifdef GLOBE_ELEVATION_FLOAT
#define GLOBE_REAL float
#define GLOBE_REAL3 vec3
#define GLOBE_FN(name) name##Float
#include "elevation_real.glsl"
#undef GLOBE_REAL
#undef GLOBE_REAL3
#undef GLOBE_FN
#endif

// = globe::Ellipsoid::position: the point at ellipsoidal height h over the unit geodetic normal n,
// p(n) + h n with p(n) = (a^2 nx, a^2 ny, b^2 nz) / sqrt(a^2 (nx^2 + ny^2) + b^2 nz^2); on a sphere
// (the specialization constant, so no branch is left) n * (a + h), bit for bit as before.
dvec3 globePosition(dvec3 n, double h) {
  if (kGlobeEllipsoid == 0u) {
    precise double r = GLOBE_ELEVATION_PARAMS.radius_m + h;
    precise dvec3 p = n * r;
    return p;
  }
  precise double a2 = GLOBE_ELEVATION_PARAMS.radius_m * GLOBE_ELEVATION_PARAMS.radius_m;
  precise double b2 = GLOBE_ELEVATION_PARAMS.polar_radius_m * GLOBE_ELEVATION_PARAMS.polar_radius_m;
  precise double inverseN = 1.0lf / sqrt(a2 * (n.x * n.x + n.y * n.y) + b2 * (n.z * n.z));
  precise dvec3 surface = dvec3(a2 * n.x * inverseN, a2 * n.y * inverseN, b2 * n.z * inverseN);
  precise dvec3 p = surface + n * h;
  return p;
}

// = globe::ElevationModel::surfacePosition: globePosition(unit_direction, elevation), metres.
dvec3 globeSurfacePosition(dvec3 unit_direction) {
  return globePosition(unit_direction, globeElevation(unit_direction));
}

#endif  // GLOBE_ELEVATION_GLSL
