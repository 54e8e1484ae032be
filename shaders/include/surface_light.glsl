// The light on a Lambertian surface of unit normal `n` through the atmosphere: the sun's
// (`sunLight` on a plane facing it, from direction `sun`), the sky's (`skyLight` on a horizontal
// plane, taken as uniform over the upper hemisphere) and the light the ground around sends back up
// (the same two on flat ground times kGroundBounceAlbedo, over the lower hemisphere). Without that
// bounce, slopes turned from the sun saw only the blue sky: metre-scale bumps at the 2 m camera
// showed as navy blotches (docs/rendering.md, "Colour").
#ifndef GLOBE_SURFACE_LIGHT_GLSL
#define GLOBE_SURFACE_LIGHT_GLSL

// The mean albedo of the ground around a point: land between forest (~0.05) and desert (~0.35).
const float kGroundBounceAlbedo = 0.15;

vec3 surfaceLight(vec3 n, vec3 sun, vec3 up, vec3 sunLight, vec3 skyLight) {
  float facingUp = dot(n, up);
  vec3 ground = kGroundBounceAlbedo * (sunLight * max(dot(up, sun), 0.0) + skyLight);
  return sunLight * max(dot(n, sun), 0.0) + skyLight * (1.0 + facingUp) * 0.5 + ground * (1.0 - facingUp) * 0.5;
}
#endif
