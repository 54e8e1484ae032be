#version 450
// Test kernel: runs the terrain vertex computation (include/terrain_vertex.glsl, the same code as
// terrain.vert) for every vertex of one instance and writes the clip positions, so tests can
// compare what the GPU projects with a double-precision projection.
#extension GL_GOOGLE_include_directive : require
#include "include/terrain_vertex.glsl"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 3) writeonly buffer Out { vec4 clip[]; };

layout(push_constant) uniform Push {
  uint drawnCells;
  uint instance;
  uint vertexCount;
  uint pad0;
} push;

void main() {
  uint v = gl_GlobalInvocationID.x;
  if (v >= push.vertexCount) return;
  clip[v] = terrainVertex(v, push.instance, push.drawnCells).clip;
}
