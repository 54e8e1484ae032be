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
#ifndef GLOBE_ELEVATION_GLSL
#define GLOBE_ELEVATION_GLSL

#include "elevation_params.h"

#ifndef GLOBE_ELEVATION_PARAMS
#error "define GLOBE_ELEVATION_PARAMS (an ElevationParams l-value) before including elevation.glsl"
#endif

// 32-bit avalanche, = globe::hashMix32.
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

  uint hx0 = globeHashMix32(globeLatticeKey(ix) + seed);
  uint hx1 = globeHashMix32(globeLatticeKey(ix + 1L) + seed);
  uint ky0 = globeLatticeKey(iy);
  uint ky1 = globeLatticeKey(iy + 1L);
  uint kz0 = globeLatticeKey(iz);
  uint kz1 = globeLatticeKey(iz + 1L);
  uint h00 = globeHashMix32(hx0 + ky0);
  uint h10 = globeHashMix32(hx1 + ky0);
  uint h01 = globeHashMix32(hx0 + ky1);
  uint h11 = globeHashMix32(hx1 + ky1);

  precise double g000 = globeGradientDot(globeHashMix32(h00 + kz0), x0, y0, z0);
  precise double g100 = globeGradientDot(globeHashMix32(h10 + kz0), x1, y0, z0);
  precise double g010 = globeGradientDot(globeHashMix32(h01 + kz0), x0, y1, z0);
  precise double g110 = globeGradientDot(globeHashMix32(h11 + kz0), x1, y1, z0);
  precise double g001 = globeGradientDot(globeHashMix32(h00 + kz1), x0, y0, z1);
  precise double g101 = globeGradientDot(globeHashMix32(h10 + kz1), x1, y0, z1);
  precise double g011 = globeGradientDot(globeHashMix32(h01 + kz1), x0, y1, z1);
  precise double g111 = globeGradientDot(globeHashMix32(h11 + kz1), x1, y1, z1);

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

// = globe::ElevationModel::elevation_m: elevation above radius_m at a unit direction, metres.
double globeElevation(dvec3 unit_direction) {
  precise double radius = GLOBE_ELEVATION_PARAMS.radius_m;
  precise double px = unit_direction.x * radius;
  precise double py = unit_direction.y * radius;
  precise double pz = unit_direction.z * radius;
  double values[GLOBE_MAX_ELEVATION_LAYERS];
  precise double total = 0.0LF;
  uint layer_count = GLOBE_ELEVATION_PARAMS.layer_count;
  for (uint l = 0u; l < layer_count; ++l) {
    precise double lacunarity = GLOBE_ELEVATION_PARAMS.layers[l].lacunarity;
    precise double gain = GLOBE_ELEVATION_PARAMS.layers[l].gain;
    precise double frequency = GLOBE_ELEVATION_PARAMS.layers[l].frequency;
    precise double amplitude = GLOBE_ELEVATION_PARAMS.layers[l].amplitude_m;
    uint seed = GLOBE_ELEVATION_PARAMS.layers[l].seed;
    uint octaves = GLOBE_ELEVATION_PARAMS.layers[l].octaves;
    uint kind = GLOBE_ELEVATION_PARAMS.layers[l].kind;
    // Scale first, octaves skipped where it is exactly 0: bit-identical, see elevation.cpp.
    int modulator = GLOBE_ELEVATION_PARAMS.layers[l].modulator;
    precise double scale = 1.0LF;
    if (modulator >= 0) {
      precise double low = GLOBE_ELEVATION_PARAMS.layers[l].modulation_low_m;
      precise double inv_range = GLOBE_ELEVATION_PARAMS.layers[l].modulation_inv_range;
      precise double floor_scale = GLOBE_ELEVATION_PARAMS.layers[l].modulation_floor;
      precise double m = (values[modulator] - low) * inv_range;
      m = min(max(m, 0.0LF), 1.0LF);
      precise double s = m * m * (3.0LF - 2.0LF * m);
      scale = floor_scale + (1.0LF - floor_scale) * s;
    }
    if (scale == 0.0LF) octaves = 0u;
    precise double sum = 0.0LF;
    for (uint o = 0u; o < octaves; ++o) {
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
    if (modulator >= 0) sum = sum * scale;
    precise double value = sum + GLOBE_ELEVATION_PARAMS.layers[l].offset_m;
    values[l] = value;
    total = total + value;
  }
  return total;
}

// = globe::ElevationModel::surfacePosition: unit_direction * (radius_m + elevation), metres.
dvec3 globeSurfacePosition(dvec3 unit_direction) {
  precise double r = GLOBE_ELEVATION_PARAMS.radius_m + globeElevation(unit_direction);
  precise dvec3 p = unit_direction * r;
  return p;
}

#endif  // GLOBE_ELEVATION_GLSL
