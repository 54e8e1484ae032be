// Land cover masks per payload sample: a mirror of globe::climateAt and globe::landCoverMasks
// (planet/surface/land_cover.cpp), in float, see land_cover_layout.h for the model. Used by the payload
// kernel (payload_generate.glsl), which includes elevation.glsl with GLOBE_ELEVATION_FLOAT first
// (for globeGradientNoiseFloat).
// GLOBE_LAND_COVER names the LandCoverParams to read (the kernel's uniform block). No branch or loop
// bound may depend on its values alone (class_count): lavapipe would compile the kernel again when
// they change (docs/rendering.md, "No shader compile per frame"), hence the constant loop bounds.
#ifndef GLOBE_LAND_COVER_GLSL
#define GLOBE_LAND_COVER_GLSL

#include "land_cover_layout.h"

#ifndef GLOBE_LAND_COVER
#error "define GLOBE_LAND_COVER (a LandCoverParams l-value) before including land_cover.glsl"
#endif

// 3 octaves, lacunarity 2, gain 0.5 (= climateNoise).
float landCoverNoise(vec3 p, uint seed) {
  precise float sum = 0.0;
  float amplitude = 1.0;
  [[unroll]] for (int o = 0; o < 3; ++o) {
    sum = sum + amplitude * globeGradientNoiseFloat(p.x, p.y, p.z, seed);
    p = p * 2.0;
    amplitude = amplitude * 0.5;
    seed = seed + 0x9e3779b9u;
  }
  return sum;
}

// x = temperature (degrees Celsius), y = moisture (0..1) at a sample: its unit direction, drawn
// elevation and the planet's first layer's value (metres).
vec2 landCoverClimate(vec3 direction, float elevation_m, float firstLayer_m) {
  vec3 q = direction * GLOBE_LAND_COVER.noise_scale;
  float nT = landCoverNoise(q, GLOBE_LAND_COVER.seed);
  float nM = landCoverNoise(q, GLOBE_LAND_COVER.seed + 1u);
  float above = elevation_m - GLOBE_LAND_COVER.sea_level_m;
  float inland = max(firstLayer_m - GLOBE_LAND_COVER.sea_level_m, 0.0);
  float lat2 = direction.z * direction.z;
  float t0 = GLOBE_LAND_COVER.equator_temperature_c;
  float temperature = t0 + (GLOBE_LAND_COVER.pole_temperature_c - t0) * lat2 +
                      GLOBE_LAND_COVER.temperature_noise_c * nT - GLOBE_LAND_COVER.lapse_rate_c_per_m * max(above, 0.0);
  float moisture = clamp(GLOBE_LAND_COVER.moisture_base + GLOBE_LAND_COVER.moisture_noise * nM -
                             GLOBE_LAND_COVER.inland_drying_per_m * inland,
                         0.0, 1.0);
  return vec2(temperature, moisture);
}

float landCoverEdge(float x, float edge, float blend) {
  float t = clamp((x - edge) / blend + 0.5, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

float landCoverBand(float x, float lo, float hi, float blend) {
  return landCoverEdge(x, lo, blend) * (1.0 - landCoverEdge(x, hi, blend));
}

// The 8 mask bytes as two RGBA8 words (class i in byte i % 4 of word i / 4), summing to 255.
uvec2 landCoverMasks(vec2 climate, float elevation_m, float cosSlope) {
  float above = elevation_m - GLOBE_LAND_COVER.sea_level_m;
  float slope = degrees(acos(clamp(cosSlope, 0.0, 1.0)));
  float w[GLOBE_MAX_LAND_COVER_CLASSES];
  float sum = 0.0;
  [[unroll]] for (uint i = 0u; i < uint(GLOBE_MAX_LAND_COVER_CLASSES); ++i) {
    LandCoverClassParams c = GLOBE_LAND_COVER.classes[i];
    float v = landCoverBand(climate.x, c.temperature_min_c, c.temperature_max_c, GLOBE_LAND_COVER.temperature_blend_c) *
              landCoverBand(climate.y, c.moisture_min, c.moisture_max, GLOBE_LAND_COVER.moisture_blend) *
              landCoverBand(above, c.elevation_min_m, c.elevation_max_m, GLOBE_LAND_COVER.elevation_blend_m) *
              landCoverBand(slope, c.slope_min_deg, c.slope_max_deg, GLOBE_LAND_COVER.slope_blend_deg);
    w[i] = i < GLOBE_LAND_COVER.class_count ? v : 0.0;
    sum += w[i];
  }
  float missing = max(1.0e-3 - sum, 0.0);
  w[0] += missing;
  sum += missing;
  uint bytes[GLOBE_MAX_LAND_COVER_CLASSES];
  uint total = 0u, largest = 0u;
  [[unroll]] for (uint i = 0u; i < uint(GLOBE_MAX_LAND_COVER_CLASSES); ++i) {
    bytes[i] = uint(floor(w[i] / sum * 255.0 + 0.5));
    total += bytes[i];
    largest = w[i] > w[largest] ? i : largest;
  }
  bytes[largest] = bytes[largest] + 255u - total;
  return uvec2(bytes[0] | (bytes[1] << 8) | (bytes[2] << 16) | (bytes[3] << 24),
               bytes[4] | (bytes[5] << 8) | (bytes[6] << 16) | (bytes[7] << 24));
}

// The masks' blend of the class colours (= globe::landCoverAlbedo).
vec3 landCoverAlbedo(uvec2 masks) {
  vec3 albedo = vec3(0.0);
  [[unroll]] for (uint i = 0u; i < uint(GLOBE_MAX_LAND_COVER_CLASSES); ++i) {
    float m = float((masks[i / 4u] >> (8u * (i % 4u))) & 0xffu) / 255.0;
    LandCoverClassParams c = GLOBE_LAND_COVER.classes[i];
    albedo += m * vec3(c.r, c.g, c.b);
  }
  return albedo;
}

#endif  // GLOBE_LAND_COVER_GLSL
