// Terrain colour: the planet's colour ramp (a mirror of globe::rampColour, planet/surface/colour_ramp.cpp,
// see shaders/include/colour_ramp_layout.h for the formula), evaluated per payload sample by the generation
// kernel (payload_generate.glsl).
#ifndef GLOBE_COLOUR_RAMP_GLSL
#define GLOBE_COLOUR_RAMP_GLSL

#extension GL_EXT_control_flow_attributes : require

#include "colour_ramp_layout.h"

// GLOBE_RAMP names the ColourRampParams to read (the payload kernel's uniform block). Not a
// parameter: passing the 320-byte struct by value copies it per call, which made lavapipe ~5x slower.
// No branch or loop bound may depend on the ramp's values alone (stop_count, snow_enabled): from a
// uniform buffer, lavapipe would inline them and compile the shader again at draw time
// (docs/rendering.md, "No shader compile per frame"). Hence the constant loop bound (the loop
// always breaks by stop n - 1: elevations increase and the last stop is handled first) and the
// snow selected with mix(bool), not an if.
#ifndef GLOBE_RAMP
#error "define GLOBE_RAMP (a ColourRampParams l-value) before including colour_ramp.glsl"
#endif
vec3 terrainRampColour(float elevation_m, float cosSlope) {
  uint n = clamp(GLOBE_RAMP.stop_count, 1u, uint(GLOBE_MAX_COLOUR_STOPS));
  vec3 base = vec3(GLOBE_RAMP.stops[0].r, GLOBE_RAMP.stops[0].g, GLOBE_RAMP.stops[0].b);
  if (elevation_m >= GLOBE_RAMP.stops[n - 1u].elevation_m) {
    base = vec3(GLOBE_RAMP.stops[n - 1u].r, GLOBE_RAMP.stops[n - 1u].g, GLOBE_RAMP.stops[n - 1u].b);
  } else {
    [[dont_unroll]] for (uint i = 1u; i < uint(GLOBE_MAX_COLOUR_STOPS); ++i) {
      if (elevation_m < GLOBE_RAMP.stops[i].elevation_m) {
        float e0 = GLOBE_RAMP.stops[i - 1u].elevation_m, e1 = GLOBE_RAMP.stops[i].elevation_m;
        float t = clamp((elevation_m - e0) / (e1 - e0), 0.0, 1.0);
        vec3 c0 = vec3(GLOBE_RAMP.stops[i - 1u].r, GLOBE_RAMP.stops[i - 1u].g, GLOBE_RAMP.stops[i - 1u].b);
        vec3 c1 = vec3(GLOBE_RAMP.stops[i].r, GLOBE_RAMP.stops[i].g, GLOBE_RAMP.stops[i].b);
        base = mix(c0, c1, t);
        break;
      }
    }
  }
  float r = clamp((GLOBE_RAMP.rock_cos_start - cosSlope) * GLOBE_RAMP.rock_inv_range, 0.0, 1.0);
  vec3 colour = mix(base, vec3(GLOBE_RAMP.rock.r, GLOBE_RAMP.rock.g, GLOBE_RAMP.rock.b), r * r * (3.0 - 2.0 * r));
  bool snowy = all(bvec2(GLOBE_RAMP.snow_enabled != 0u, cosSlope >= GLOBE_RAMP.snow_cos_min));
  float s = clamp((elevation_m - GLOBE_RAMP.snow_elevation_m) * GLOBE_RAMP.snow_inv_blend, 0.0, 1.0);
  vec3 snowed = mix(colour, vec3(GLOBE_RAMP.snow.r, GLOBE_RAMP.snow.g, GLOBE_RAMP.snow.b), s);
  colour = mix(colour, snowed, bvec3(snowy));  // a select: colour unchanged, bit for bit, without snow
  return colour;
}

#endif  // GLOBE_COLOUR_RAMP_GLSL
