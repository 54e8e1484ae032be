// The debug colour of a drawn level: distinct and saturated (golden-ratio hue steps).
#ifndef GLOBE_TERRAIN_LEVEL_COLOUR_GLSL
#define GLOBE_TERRAIN_LEVEL_COLOUR_GLSL

vec3 terrainLevelColour(uint level) {
  float hue = fract(float(level) * 0.618034);
  vec3 k = clamp(abs(fract(hue + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
  return mix(vec3(0.15), k, 0.85);
}

// The key colour of the dominant class among the 8 masks (the land cover debug view): class i has
// level i's colour.
vec3 terrainLandCoverColour(vec4 cover0, vec4 cover1) {
  uint best = 0u;
  float most = -1.0;
  for (uint i = 0u; i < 8u; ++i) {
    float w = i < 4u ? cover0[i] : cover1[i - 4u];
    best = w > most ? i : best;
    most = max(most, w);
  }
  return terrainLevelColour(best);
}

#endif  // GLOBE_TERRAIN_LEVEL_COLOUR_GLSL
