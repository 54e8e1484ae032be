#version 450
#extension GL_GOOGLE_include_directive : require
// Background behind the terrain: the atmosphere's sky, from the ground or from space (limb glow),
// and the sun's disc seen through it (include/atmosphere.glsl). Only pixels no terrain covered are
// shaded (depth test against the far plane, no depth written). The vertex stage interpolates the
// smooth part, tone-mapped (terrain_sky.vert); here the sun's disc per pixel, and, seen from outside
// the atmosphere, the whole sky for the rays through it (the limb is a few pixels wide).
#define GLOBE_ATMOSPHERE_BINDING 0
#include "include/atmosphere.glsl"
#include "include/display_encoding.glsl"

layout(location = 0) in vec3 inRay;
layout(location = 1) in vec3 inSky;
layout(location = 2) in vec3 inDisc;
layout(location = 3) in float inShell;
layout(location = 0) out vec4 outColour;

// 1: the camera is outside the atmosphere (TerrainRenderer picks the pipeline per frame).
layout(constant_id = 0) const uint kFromSpace = 0u;

layout(push_constant) uniform Push {
  vec4 right;  // see terrain_sky.vert
  vec4 up;
  vec4 forward;
  vec4 camera;
  vec4 sun;
} push;

void main() {
  vec3 v = normalize(inRay);
  vec3 sun = push.sun.xyz;
  vec3 sky = inSky, disc = inDisc;
  // Seen from outside (a specialization constant: a uniform condition would make lavapipe compile
  // variants), a branch on the interpolated value: per pixel only near the shell, where
  // atmosphereSky is black for rays that miss.
  if (kFromSpace != 0u && inShell > 0.0) {
    vec3 transmittance;
    sky = atmosphereExposed(atmosphereSky(push.camera.xyz, v, sun, transmittance));
    float alpha = atmosphere.sun.w;
    disc = atmosphereExposed(atmosphere.sun.rgb / (kAtmospherePi * alpha * alpha) * transmittance);
  }
  // The sun's disc over the sky (the display transform rolls both off to white).
  sky += mix(vec3(0.0), disc, bvec3(dot(v, sun) > atmosphere.misc.w));
  outColour = encodeScene(sky, 1.0);
}
