#version 450
// Node payloads in double precision: the engine's kernel (body in include/payload_generate.glsl).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

#include "include/payload_generate.glsl"
