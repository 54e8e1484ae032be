#version 450
// Terrain shading (body in include/terrain_fragment.glsl).
#extension GL_GOOGLE_include_directive : require

#include "include/terrain_fragment.glsl"
