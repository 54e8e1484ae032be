#version 450
// The terrain vertex stage: positions read from the payload (body in include/terrain_vertex_stage.glsl).
#extension GL_GOOGLE_include_directive : require
#include "include/terrain_vertex_stage.glsl"
