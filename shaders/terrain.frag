#version 450
// Terrain shading: Lambert light from the sun on the interpolated (morphed) normal, colour from the
// planet's ramp by elevation and slope; or a debug colour per drawn level.
#extension GL_GOOGLE_include_directive : require
#include "include/terrain_layout.h"

layout(std430, set = 0, binding = 0) readonly buffer TerrainFrameBuffer {
  TerrainFrame frame;
  TerrainInstance instances[];
};
#define GLOBE_RAMP frame.ramp
#include "include/terrain_shading.glsl"

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec3 inUp;
layout(location = 2) in float inElevation;
layout(location = 3) flat in uint inLevel;
layout(location = 4) in vec3 inRelative;
layout(location = 0) out vec4 outColour;

void main() {
  uint debugView = frame.options.y;
  if (debugView != GLOBE_TERRAIN_SHADED) {
    outColour = vec4(terrainLevelColour(inLevel), 1.0);
    return;
  }
  vec3 n = normalize(inNormal);
  vec3 up = normalize(inUp);
  vec3 albedo = terrainRampColour(inElevation, clamp(dot(n, up), 0.0, 1.0));
  float light = frame.sun.w + (1.0 - frame.sun.w) * max(dot(n, frame.sun.xyz), 0.0);
  outColour = vec4(albedo * light, 1.0);
}
