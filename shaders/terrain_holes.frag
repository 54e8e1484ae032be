#version 450
// Terrain shading for planets with kept no-data holes (nodata = "hole", docs/elevation-data.md):
// terrain.frag plus the discard inside holes and a dark rim at their border.
#extension GL_GOOGLE_include_directive : require

#define GLOBE_TERRAIN_HOLES
#include "include/terrain_fragment.glsl"
