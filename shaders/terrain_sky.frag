#version 450
#extension GL_GOOGLE_include_directive : require
#include "include/display_encoding.glsl"
// Background behind the terrain: a cheap sky gradient by the angle between the view ray and the
// local vertical, fading to black space as the camera climbs through the atmosphere height.
// No depth written (the depth buffer stays at its clear value 0 = infinitely far).
layout(location = 0) in vec3 inRay;
layout(location = 1) in float inUp;
layout(location = 0) out vec4 outColour;

layout(push_constant) uniform Push {
  vec4 right;    // see terrain_sky.vert
  vec4 up;
  vec4 forward;
  vec4 zenith;   // rgb: sky colour straight up; w: atmosphere factor (1 at the ground, 0 in space)
  vec4 horizon;  // rgb: sky colour at the horizon
  vec4 local;
} push;

void main() {
  float t = inUp * inversesqrt(dot(inRay, inRay));  // cosine of the ray's angle to the vertical
  vec3 sky = mix(push.horizon.rgb, push.zenith.rgb, sqrt(clamp(t, 0.0, 1.0)));
  outColour = encodeDisplay(sky * push.zenith.w, 1.0);
}
