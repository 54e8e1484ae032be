#version 450
// Terrain shading for nodes with sea (planets with [water]): terrain.frag plus the water surface
// below sea level, shaded per fragment.
#extension GL_GOOGLE_include_directive : require

#define GLOBE_TERRAIN_WATER
#include "include/terrain_fragment.glsl"
