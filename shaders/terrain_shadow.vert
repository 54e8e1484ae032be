#version 450
// The terrain's depth seen from the sun, for its shadow maps (engine/render/terrain_shadows.h): the
// vertex computation of the camera's pass (include/terrain_vertex.glsl: the same payload positions
// and morph, the camera-relative position), projected by the cascade's matrix in the frame constants.
#extension GL_GOOGLE_include_directive : require
#include "include/terrain_vertex.glsl"

layout(push_constant) uniform Push {
  TerrainDrawPush draw;
} push;

void main() {
  gl_Position = terrainVertex(uint(gl_VertexIndex), uint(gl_InstanceIndex), push.draw.drawnCells).clip;
}
