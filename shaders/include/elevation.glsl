// GLSL mirror of the CPU elevation reference (planet/gradient_noise.h, planet/elevation.cpp). Every
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

// = globe::gradientDot: Perlin's 16 gradients (12 cube edges), index = top 4 bits of the hash.
double globeGradientDot(uint hash, double x, double y, double z) {
  uint h = hash >> 28;
  double u = h < 8u ? x : y;
  double v = h < 4u ? y : ((h == 12u || h == 14u) ? x : z);
  precise double a = (h & 1u) == 0u ? u : -u;
  precise double b = (h & 2u) == 0u ? v : -v;
  precise double r = a + b;
  return r;
}

double globeNoiseFade(double t) {
  precise double r = t * t * t * (t * (t * 6.0LF - 15.0LF) + 10.0LF);
  return r;
}

double globeNoiseLerp(double a, double b, double t) {
  precise double r = a + t * (b - a);
  return r;
}

// = globe::gradientNoise<double>.
double globeGradientNoise(double x, double y, double z, uint seed) {
  precise double fx = floor(x);
  precise double fy = floor(y);
  precise double fz = floor(z);
  int64_t ix = int64_t(fx);
  int64_t iy = int64_t(fy);
  int64_t iz = int64_t(fz);
  precise double x0 = x - fx;
  precise double y0 = y - fy;
  precise double z0 = z - fz;
  precise double x1 = x0 - 1.0LF;
  precise double y1 = y0 - 1.0LF;
  precise double z1 = z0 - 1.0LF;

  // = globe::latticeWordX/Y/Z, then one globe::latticeCornerHash per corner.
  uint wx0 = globeLatticeKey(ix) * 0x9e3779b1u;
  uint wx1 = globeLatticeKey(ix + 1L) * 0x9e3779b1u;
  uint wy0 = globeLatticeKey(iy) * 0x85ebca77u;
  uint wy1 = globeLatticeKey(iy + 1L) * 0x85ebca77u;
  uint wz0 = globeLatticeKey(iz) * 0xc2b2ae3du;
  uint wz1 = globeLatticeKey(iz + 1L) * 0xc2b2ae3du;
  precise double g000 = globeGradientDot(globeLatticeCornerHash(wx0, wy0, wz0, seed), x0, y0, z0);
  precise double g100 = globeGradientDot(globeLatticeCornerHash(wx1, wy0, wz0, seed), x1, y0, z0);
  precise double g010 = globeGradientDot(globeLatticeCornerHash(wx0, wy1, wz0, seed), x0, y1, z0);
  precise double g110 = globeGradientDot(globeLatticeCornerHash(wx1, wy1, wz0, seed), x1, y1, z0);
  precise double g001 = globeGradientDot(globeLatticeCornerHash(wx0, wy0, wz1, seed), x0, y0, z1);
  precise double g101 = globeGradientDot(globeLatticeCornerHash(wx1, wy0, wz1, seed), x1, y0, z1);
  precise double g011 = globeGradientDot(globeLatticeCornerHash(wx0, wy1, wz1, seed), x0, y1, z1);
  precise double g111 = globeGradientDot(globeLatticeCornerHash(wx1, wy1, wz1, seed), x1, y1, z1);

  precise double u = globeNoiseFade(x0);
  precise double v = globeNoiseFade(y0);
  precise double w = globeNoiseFade(z0);
  precise double a00 = globeNoiseLerp(g000, g100, u);
  precise double a10 = globeNoiseLerp(g010, g110, u);
  precise double a01 = globeNoiseLerp(g001, g101, u);
  precise double a11 = globeNoiseLerp(g011, g111, u);
  precise double b0 = globeNoiseLerp(a00, a10, v);
  precise double b1 = globeNoiseLerp(a01, a11, v);
  precise double r = globeNoiseLerp(b0, b1, w);
  return r;
}

// Layer l of globe::ElevationModel::elevation_m. l is a literal at every call, so after inlining
// the octave count, kind and modulator are constants and the octave loop unrolls (lavapipe keeps no
// loop-carried value in registers across a loop's iterations).
void globeElevationLayer(uint l, double px, double py, double pz, inout double values[GLOBE_MAX_ELEVATION_LAYERS],
                         inout double total) {
  precise double lacunarity = GLOBE_ELEVATION_PARAMS.layers[l].lacunarity;
  precise double gain = GLOBE_ELEVATION_PARAMS.layers[l].gain;
  precise double frequency = GLOBE_ELEVATION_PARAMS.layers[l].frequency;
  precise double amplitude = GLOBE_ELEVATION_PARAMS.layers[l].amplitude_m;
  uint seed = GLOBE_ELEVATION_PARAMS.layers[l].seed;
  uint octaves = globeLayerOctaves(l);
  uint kind = globeLayerKind(l);
  int modulator = globeLayerModulator(l);
  // Scale first, octaves skipped where it is exactly 0: bit-identical, see elevation.cpp.
  precise double scale = 1.0LF;
  if (modulator >= 0) {
    precise double low = GLOBE_ELEVATION_PARAMS.layers[l].modulation_low_m;
    precise double inv_range = GLOBE_ELEVATION_PARAMS.layers[l].modulation_inv_range;
    precise double floor_scale = GLOBE_ELEVATION_PARAMS.layers[l].modulation_floor;
    precise double m = (values[max(modulator, 0)] - low) * inv_range;
    m = min(max(m, 0.0LF), 1.0LF);
    precise double s = m * m * (3.0LF - 2.0LF * m);
    scale = floor_scale + (1.0LF - floor_scale) * s;
  }
  precise double sum = 0.0LF;
  if (scale != 0.0LF) {
    [[unroll]] for (uint o = 0u; o < octaves; ++o) {
      precise double n = globeGradientNoise(px * frequency, py * frequency, pz * frequency, seed);
      precise double t = n;
      if (kind == GLOBE_LAYER_RIDGED) {
        precise double c = 1.0LF - abs(n);
        t = c * c;
      } else if (kind == GLOBE_LAYER_BILLOW) {
        t = abs(n);
      }
      sum = sum + amplitude * t;
      frequency = frequency * lacunarity;
      amplitude = amplitude * gain;
      seed = seed + 0x9e3779b9u;
    }
  }
  if (modulator >= 0) sum = sum * scale;
  precise double value = sum + GLOBE_ELEVATION_PARAMS.layers[l].offset_m;
  values[l] = value;
  total = total + value;
}

// = globe::ElevationModel::elevation_m: elevation above radius_m at a unit direction, metres.
double globeElevation(dvec3 unit_direction) {
  precise double radius = GLOBE_ELEVATION_PARAMS.radius_m;
  precise double px = unit_direction.x * radius;
  precise double py = unit_direction.y * radius;
  precise double pz = unit_direction.z * radius;
  double values[GLOBE_MAX_ELEVATION_LAYERS];
  precise double total = 0.0LF;
  // Unrolled by hand: the compiler won't unroll a loop that holds another.
  globeElevationLayer(0u, px, py, pz, values, total);
  if (kGlobeLayerCount > 1u) globeElevationLayer(1u, px, py, pz, values, total);
  if (kGlobeLayerCount > 2u) globeElevationLayer(2u, px, py, pz, values, total);
  if (kGlobeLayerCount > 3u) globeElevationLayer(3u, px, py, pz, values, total);
  if (kGlobeLayerCount > 4u) globeElevationLayer(4u, px, py, pz, values, total);
  if (kGlobeLayerCount > 5u) globeElevationLayer(5u, px, py, pz, values, total);
  if (kGlobeLayerCount > 6u) globeElevationLayer(6u, px, py, pz, values, total);
  if (kGlobeLayerCount > 7u) globeElevationLayer(7u, px, py, pz, values, total);
  return total;
}

// = globe::ElevationModel::surfacePosition: unit_direction * (radius_m + elevation), metres.
dvec3 globeSurfacePosition(dvec3 unit_direction) {
  precise double r = GLOBE_ELEVATION_PARAMS.radius_m + globeElevation(unit_direction);
  precise dvec3 p = unit_direction * r;
  return p;
}

#endif  // GLOBE_ELEVATION_GLSL
