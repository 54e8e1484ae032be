// The debug colour of a drawn level: distinct and saturated (golden-ratio hue steps).
#ifndef GLOBE_TERRAIN_LEVEL_COLOUR_GLSL
#define GLOBE_TERRAIN_LEVEL_COLOUR_GLSL

vec3 terrainLevelColour(uint level) {
  float hue = fract(float(level) * 0.618034);
  vec3 k = clamp(abs(fract(hue + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
  return mix(vec3(0.15), k, 0.85);
}

#endif  // GLOBE_TERRAIN_LEVEL_COLOUR_GLSL
