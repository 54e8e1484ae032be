#version 450
// Test kernel: one triangle whose clip-space corners come from push constants.
layout(push_constant) uniform Push {
  vec4 corners[3];  // clip-space xyzw
  vec4 colour;      // linear RGBA
} push;

void main() { gl_Position = push.corners[gl_VertexIndex]; }
