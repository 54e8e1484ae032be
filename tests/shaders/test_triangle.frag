#version 450
#extension GL_GOOGLE_include_directive : require
#include "include/display_encoding.glsl"
layout(push_constant) uniform Push {
  vec4 corners[3];
  vec4 colour;
} push;
layout(location = 0) out vec4 outColour;

void main() { outColour = encodeDisplay(push.colour.rgb, push.colour.a); }
