// Terrain colours: the planet's colour ramp (a mirror of globe::rampColour, planet/colour_ramp.cpp,
// see shaders/include/colour_ramp.h for the formula) and the debug colours per level.
#ifndef GLOBE_TERRAIN_SHADING_GLSL
#define GLOBE_TERRAIN_SHADING_GLSL

#include "colour_ramp.h"

vec3 terrainRampColour(ColourRampParams ramp, float elevation_m, float cosSlope) {
  uint n = clamp(ramp.stop_count, 1u, uint(GLOBE_MAX_COLOUR_STOPS));
  ColourStop last = ramp.stops[n - 1u];
  vec3 base = vec3(ramp.stops[0].r, ramp.stops[0].g, ramp.stops[0].b);
  if (elevation_m >= last.elevation_m) {
    base = vec3(last.r, last.g, last.b);
  } else {
    for (uint i = 1u; i < n; ++i) {
      if (elevation_m < ramp.stops[i].elevation_m) {
        ColourStop a = ramp.stops[i - 1u], b = ramp.stops[i];
        float t = clamp((elevation_m - a.elevation_m) / (b.elevation_m - a.elevation_m), 0.0, 1.0);
        base = mix(vec3(a.r, a.g, a.b), vec3(b.r, b.g, b.b), t);
        break;
      }
    }
  }
  float r = clamp((ramp.rock_cos_start - cosSlope) * ramp.rock_inv_range, 0.0, 1.0);
  vec3 colour = mix(base, vec3(ramp.rock.r, ramp.rock.g, ramp.rock.b), r * r * (3.0 - 2.0 * r));
  if (ramp.snow_enabled != 0u && cosSlope >= ramp.snow_cos_min) {
    float s = clamp((elevation_m - ramp.snow_elevation_m) * ramp.snow_inv_blend, 0.0, 1.0);
    colour = mix(colour, vec3(ramp.snow.r, ramp.snow.g, ramp.snow.b), s);
  }
  return colour;
}

// A distinct, saturated colour per drawn level (golden-ratio hue steps).
vec3 terrainLevelColour(uint level) {
  float hue = fract(float(level) * 0.618034);
  vec3 k = clamp(abs(fract(hue + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
  return mix(vec3(0.15), k, 0.85);
}

#endif  // GLOBE_TERRAIN_SHADING_GLSL
