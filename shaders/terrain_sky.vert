#version 450
#extension GL_GOOGLE_include_directive : require
// The sky's vertex stage (shaders/terrain_sky.frag): a screen grid of n x n cells at the far plane
// (drawn with the terrain's index buffer: vertex i + j (n + 1), n = push.forward.w), the atmosphere's
// sky evaluated once at each vertex, tone-mapped, and interpolated. The sky is smooth where it
// covers much of the screen (seen from inside the atmosphere), the Mie halo round the sun too at a
// few degrees per cell; per pixel, lavapipe paid ~20 table loads for every sky pixel (+50 % on the
// flyover, docs/rendering.md "Atmosphere"). What is sharp stays per pixel in the fragment stage:
// the sun's disc, and the limb seen from outside the atmosphere. Rays below the horizon (under the terrain)
// take the sky just above it, so no cell blends the ground's light into the sky.
#define GLOBE_ATMOSPHERE_BINDING 0
#include "include/atmosphere.glsl"

layout(location = 0) out vec3 outRay;   // unnormalised view ray, camera axes scaled by the fov
layout(location = 1) out vec3 outSky;   // tone-mapped sky, phases applied
layout(location = 2) out vec3 outDisc;  // tone-mapped sun's disc seen through the atmosphere
// > 0 near rays that cross the atmosphere's shell seen from outside it (the fragment stage
// evaluates those per pixel); -1 from inside, where the interpolated sky is used.
layout(location = 3) out float outShell;

layout(push_constant) uniform Push {
  vec4 right;    // xyz: unit right, w: tan(horizontal fov / 2)
  vec4 up;       // xyz: unit up, w: tan(vertical fov / 2)
  vec4 forward;  // xyz: unit view direction, w: grid cells per side
  vec4 camera;   // xyz: camera minus planet centre, metres (from doubles)
  vec4 sun;      // xyz: unit direction towards the sun
} push;

void main() {
  int side = int(push.forward.w) + 1;
  vec2 ndc = vec2(gl_VertexIndex % side, gl_VertexIndex / side) / float(side - 1) * 2.0 - 1.0;
  outRay = push.forward.xyz + ndc.x * push.right.w * push.right.xyz - ndc.y * push.up.w * push.up.xyz;
  vec3 v = normalize(outRay);
  // Inside the atmosphere, keep the ray at least just above the horizon.
  vec3 c = push.camera.xyz;
  float r = length(c);
  vec3 zenith = c / max(r, 1.0);
  float muHorizon = -sqrt(max(1.0 - (atmBottom() / max(r, atmBottom())) * (atmBottom() / max(r, atmBottom())), 0.0));
  float mu = dot(v, zenith);
  vec3 level = v - mu * zenith;
  float muMin = min(muHorizon + 0.02, 1.0);
  vec3 lifted = muMin * zenith + sqrt(max(1.0 - muMin * muMin, 0.0)) * level / max(length(level), 1e-6);
  v = mix(v, lifted, bvec3(mu < muMin && r < atmTop()));
  vec4 entry = atmosphereEntry(c, v);
  vec4 ray = atmosphereRay(entry.xyz, v, push.sun.xyz);
  bool hitsGround = atmRayHitsGround(ray.x, ray.y);
  bool misses = entry.w < 0.0;
  // The phases with the vertex's own ray (v before the lift: the sun's halo stays round the sun).
  vec4 s = atmScattering(ray.x, ray.y, ray.z, ray.w, hitsGround);
  vec3 sky = atmosphereInscatter(s, dot(normalize(outRay), push.sun.xyz), ray.z);
  // Seen from outside the atmosphere the fragment stage evaluates every ray through the shell per
  // pixel: a vertex's value there would blend the lit ground's air into the space beside the limb.
  bool outside = dot(c, c) > atmTop() * atmTop();
  outSky = atmosphereToneMap(mix(sky, vec3(0.0), bvec3(misses || outside)));
  vec3 transmittance = mix(atmTransmittanceToTop(ray.x, ray.y), vec3(float(misses)), bvec3(hitsGround || misses));
  float alpha = atmosphere.sun.w;
  outDisc = atmosphereToneMap(atmosphere.sun.rgb / (kAtmospherePi * alpha * alpha) * transmittance);
  // The impact parameter squared against the top's, with a margin of a few grid cells (a cell's
  // rays are interpolated linearly, the shell's edge is a circle on screen).
  vec3 offAxis = cross(c, normalize(outRay));
  float top2 = atmTop() * atmTop();
  outShell = mix(-1.0, 1.5 * top2 - dot(offAxis, offAxis), float(dot(c, c) > top2));
  gl_Position = vec4(ndc, 0.0, 1.0);
}
