#version 450
// Terrain shading through the atmosphere on planets with kept no-data holes.
#extension GL_GOOGLE_include_directive : require

#define GLOBE_TERRAIN_ATMOSPHERE
#define GLOBE_TERRAIN_HOLES
#include "include/terrain_fragment.glsl"
