#version 450
layout(push_constant) uniform Push {
  vec4 corners[3];
  vec4 colour;
} push;
layout(location = 0) out vec4 outColour;

void main() { outColour = push.colour; }
