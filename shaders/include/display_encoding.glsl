// Colour -> what the scene's 8-bit UNORM target stores. Every fragment shader writing the scene
// target ends with outColour = encodeScene(...) for lit scene values, through one display transform
// for every preset and atmosphere detail (docs/rendering.md, "Colour"), or encodeDisplay(...) for
// unlit colours (debug views, markers) shown as they are. Scene values are exposed light: a white
// Lambertian surface facing the sun above the air is 1 (the atmosphere's `exposure` scales its
// radiance so; without one, the Lambert light is already so).
#ifndef GLOBE_DISPLAY_ENCODING_GLSL
#define GLOBE_DISPLAY_ENCODING_GLSL
#include "display_encoding.h"

// A filmic shoulder: linear (the albedos as measured) up to the knee, then rolling off to white
// with slope 1 at the knee, so sunlit snow, cloud-bright sky and the sun's disc keep their shape
// instead of clipping, and the ground keeps its colour.
vec3 displayTone(vec3 scene) {
  const float knee = float(GLOBE_DISPLAY_TONE_KNEE);
  vec3 x = max(scene, vec3(0.0));
  return min(x, vec3(knee)) + (1.0 - knee) * (vec3(1.0) - exp(-max(x - knee, 0.0) / (1.0 - knee)));
}

// Linear [0, 1] display colour -> the target's encoding (display_encoding.h).
vec4 encodeDisplay(vec3 linear, float alpha) {
  const float a = float(GLOBE_DISPLAY_ENCODING_A);
  vec3 c = clamp(linear, 0.0, 1.0);
  return vec4(a * sqrt(c) - (a - 1.0) * c, alpha);
}

vec4 encodeScene(vec3 scene, float alpha) { return encodeDisplay(displayTone(scene), alpha); }
#endif
