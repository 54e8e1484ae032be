#version 450
// Terrain shading (body in include/terrain_fragment.glsl). The build compiles it once more per
// combination of GLOBE_TERRAIN_ATMOSPHERE, GLOBE_TERRAIN_NORMAL_MAPS, GLOBE_TERRAIN_WATER and
// GLOBE_TERRAIN_HOLES as terrain[_atmosphere][_maps][_water][_holes].frag (shaders/CMakeLists.txt).
#extension GL_GOOGLE_include_directive : require

#include "include/terrain_fragment.glsl"
