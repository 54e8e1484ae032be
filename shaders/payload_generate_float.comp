#version 450
// Node payloads with the elevation and the planet-centred positions in float: only to measure what
// double buys (GenerationPrecision::kFloat, `globe trade`). Never the engine's default.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

#define GLOBE_PAYLOAD_FLOAT
#include "include/payload_generate.glsl"
