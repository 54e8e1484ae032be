#version 450
// Terrain shading through the atmosphere for nodes with sea.
#extension GL_GOOGLE_include_directive : require

#define GLOBE_TERRAIN_ATMOSPHERE
#define GLOBE_TERRAIN_WATER
#include "include/terrain_fragment.glsl"
