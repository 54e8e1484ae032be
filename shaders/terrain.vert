#version 450
// Terrain: one instance per selected node, vertices pulled from the node's payload slot
// (shaders/include/terrain_vertex.glsl does the work, shared with the readback test kernel).
#extension GL_GOOGLE_include_directive : require
#include "include/terrain_vertex.glsl"

layout(push_constant) uniform Push {
  TerrainDrawPush draw;
} push;

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec3 outUp;
layout(location = 2) out float outElevation;
layout(location = 3) flat out uint outLevel;
layout(location = 4) out vec3 outRelative;

void main() {
  TerrainVertex v = terrainVertex(uint(gl_VertexIndex), uint(gl_InstanceIndex), push.draw.drawnCells);
  gl_Position = v.clip;
  outNormal = v.normal;
  outUp = v.up;
  outElevation = v.elevation;
  outLevel = instances[gl_InstanceIndex].info.z;
  outRelative = v.relative;
}
