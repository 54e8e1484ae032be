#version 450
// The terrain vertex stage with aerial perspective and sunlight through the atmosphere (planets with
// an [atmosphere]; body in include/terrain_vertex_stage.glsl, atmosphere in include/terrain_atmosphere.glsl).
#extension GL_GOOGLE_include_directive : require
#define GLOBE_TERRAIN_ATMOSPHERE
#include "include/terrain_vertex_stage.glsl"
