#version 450
// The terrain vertex stage with positions re-projected from the payload heights every frame, in
// double (VertexPositions::kReprojected): only to measure the primary source's alternative
// (`globe trade`). Needs shaderFloat64 in the vertex stage.
#extension GL_GOOGLE_include_directive : require
#define GLOBE_TERRAIN_REPROJECT
#include "include/terrain_vertex_stage.glsl"
