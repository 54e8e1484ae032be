#version 450
#extension GL_GOOGLE_include_directive : require
// The sky's vertex stage (shaders/terrain_sky.frag): a screen grid of n x n cells at the far plane
// (drawn with the terrain's index buffer: vertex i + j (n + 1), n = push.forward.w), the atmosphere's
// sky evaluated once at each vertex, tone-mapped, and interpolated. The sky is smooth where it
// covers much of the screen (seen from inside the atmosphere), the Mie halo round the sun too at a
// few degrees per cell; per pixel, lavapipe paid ~20 table loads for every sky pixel (+50 % on the
// flyover, docs/rendering.md "Atmosphere"). What is sharp stays per pixel in the fragment stage:
// the sun's disc; from outside the atmosphere the whole sky, on a ring round the planet (kFromSpace).
// Rays below the horizon (under the terrain) take the sky just above it, so no cell blends the
// ground's light into the sky.
#define GLOBE_ATMOSPHERE_BINDING 0
#include "include/atmosphere.glsl"

layout(location = 0) out vec3 outRay;   // unnormalised view ray, camera axes scaled by the fov
layout(location = 1) out vec3 outSky;   // tone-mapped sky, phases applied
layout(location = 2) out vec3 outDisc;  // tone-mapped sun's disc seen through the atmosphere
// 1 on the ring seen from space (the fragment stage evaluates per pixel); -1 from inside, where
// the interpolated sky is used.
layout(location = 3) out float outShell;

layout(push_constant) uniform Push {
  vec4 right;    // xyz: unit right, w: tan(horizontal fov / 2)
  vec4 up;       // xyz: unit up, w: tan(vertical fov / 2)
  vec4 forward;  // xyz: unit view direction, w: grid cells per side
  vec4 camera;   // xyz: camera minus planet centre, w: radius of the lowest terrain, metres (from doubles)
  vec4 sun;      // xyz: unit direction towards the sun
} push;

// 1: the camera is outside the atmosphere (TerrainRenderer picks the pipeline per frame): the grid
// becomes a ring round the planet covering the rays that cross the atmosphere, every one of its
// pixels evaluated per pixel, and a second instance a square round the sun; the rest of the
// background stays the clear colour, black space.
// lavapipe runs a fragment branch's code for every pixel of a draw, so a screen-wide grid with the
// per-pixel evaluation behind a branch cost 18 ms a frame from 2e7 m although the limb is thin.
layout(constant_id = 0) const uint kFromSpace = 0u;

// Vertex i + j (n + 1) of the ring: i round the planet, j outwards from the lowest terrain's edge
// to just beyond the atmosphere's, on the cone of rays through them (tan of the angle off the
// planet's centre; the outer polygon circumscribes the top's circle).
vec3 ringRay(vec3 c) {
  int n = int(push.forward.w);
  int i = gl_VertexIndex % (n + 1), j = gl_VertexIndex / (n + 1);
  float r = length(c);
  vec3 centre = -c / r;
  vec3 a1 = normalize(cross(centre, abs(centre.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0)));
  vec3 a2 = cross(centre, a1);
  float s0 = min(push.camera.w / r, 0.999999), s1 = min(atmTop() / r, 0.999999);
  float t0 = s0 / sqrt(1.0 - s0 * s0);
  float t1 = s1 / sqrt(1.0 - s1 * s1) / cos(kAtmospherePi / float(n));
  float phi = 2.0 * kAtmospherePi * float(i) / float(n);
  return normalize(centre + mix(t0, t1, float(j) / float(n)) * (cos(phi) * a1 + sin(phi) * a2));
}

// Corner gl_VertexIndex (0-5, two triangles) of a square round the sun's disc, twice its angular
// radius, so that the sun is drawn in open space too (instance 1 of the draw from space).
vec3 sunSquareRay() {
  const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
  vec3 sun = push.sun.xyz;
  vec3 a1 = normalize(cross(sun, abs(sun.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0)));
  vec3 a2 = cross(sun, a1);
  vec2 corner = corners[gl_VertexIndex % 6] * 2.0 * tan(atmosphere.sun.w);
  return normalize(sun + corner.x * a1 + corner.y * a2);
}

void main() {
  if (kFromSpace != 0u) {
    vec3 v = gl_InstanceIndex == 0 ? ringRay(push.camera.xyz) : sunSquareRay();
    outRay = v;  // interpolated perspective-correctly: the pixel's own ray, up to scale
    outSky = vec3(0.0);
    outDisc = vec3(0.0);
    outShell = 1.0;
    // Clip space of the far plane (depth 0), so the rays behind the camera are clipped.
    float w = dot(v, push.forward.xyz);
    gl_Position = vec4(dot(v, push.right.xyz) / push.right.w, -dot(v, push.up.xyz) / push.up.w, 0.0, w);
    return;
  }
  int side = int(push.forward.w) + 1;
  vec2 ndc = vec2(gl_VertexIndex % side, gl_VertexIndex / side) / float(side - 1) * 2.0 - 1.0;
  outRay = push.forward.xyz + ndc.x * push.right.w * push.right.xyz - ndc.y * push.up.w * push.up.xyz;
  vec3 v = normalize(outRay);
  // Keep the ray at least just above the horizon.
  vec3 c = push.camera.xyz;
  float r = length(c);
  vec3 zenith = c / max(r, 1.0);
  float muHorizon = -sqrt(max(1.0 - (atmBottom() / max(r, atmBottom())) * (atmBottom() / max(r, atmBottom())), 0.0));
  float mu = dot(v, zenith);
  vec3 level = v - mu * zenith;
  float muMin = min(muHorizon + 0.02, 1.0);
  vec3 lifted = muMin * zenith + sqrt(max(1.0 - muMin * muMin, 0.0)) * level / max(length(level), 1e-6);
  v = mix(v, lifted, bvec3(mu < muMin));  // this grid is drawn from inside the atmosphere only
  vec4 entry = atmosphereEntry(c, v);
  vec4 ray = atmosphereRay(entry.xyz, v, push.sun.xyz);
  bool hitsGround = atmRayHitsGround(ray.x, ray.y);
  bool misses = entry.w < 0.0;
  // The phases with the vertex's own ray (v before the lift: the sun's halo stays round the sun).
  vec4 s = atmScattering(ray.x, ray.y, ray.z, ray.w, hitsGround);
  vec3 sky = atmosphereInscatter(s, dot(normalize(outRay), push.sun.xyz), ray.z);
  outSky = atmosphereExposed(mix(sky, vec3(0.0), bvec3(misses)));
  vec3 transmittance = mix(atmTransmittanceToTop(ray.x, ray.y), vec3(float(misses)), bvec3(hitsGround || misses));
  float alpha = atmosphere.sun.w;
  outDisc = atmosphereExposed(atmosphere.sun.rgb / (kAtmospherePi * alpha * alpha) * transmittance);
  outShell = -1.0;
  gl_Position = vec4(ndc, 0.0, 1.0);
}
