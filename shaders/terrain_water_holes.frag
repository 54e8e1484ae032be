#version 450
// Terrain shading for nodes with sea on planets with kept no-data holes: both variants at once.
#extension GL_GOOGLE_include_directive : require

#define GLOBE_TERRAIN_WATER
#define GLOBE_TERRAIN_HOLES
#include "include/terrain_fragment.glsl"
