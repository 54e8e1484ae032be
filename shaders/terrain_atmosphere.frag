#version 450
// Terrain shading through the atmosphere (body in include/terrain_fragment.glsl).
#extension GL_GOOGLE_include_directive : require

#define GLOBE_TERRAIN_ATMOSPHERE
#include "include/terrain_fragment.glsl"
