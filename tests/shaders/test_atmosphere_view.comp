#version 450
// Test kernel (tests/engine/atmosphere_render_test.cpp): for camera-relative points, the aerial
// perspective of the exact evaluation and as the terrain's vertex stage has it (the per-frame table
// within its reach, include/terrain_atmosphere.glsl). Bindings 3-8 are the terrain's.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "include/terrain_atmosphere.glsl"

layout(std430, set = 0, binding = 0) readonly buffer Points { vec4 points[]; };  // xyz: metres from the camera
// Per point: exact in-scattered light, exact transmittance, the table's two.
layout(std430, set = 0, binding = 1) writeonly buffer Results { vec4 results[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(points.length())) return;
  vec3 relative = points[i].xyz;
  vec3 sun = atmosphereView.sun.xyz;
  float distance = length(relative);
  vec3 v = relative / max(distance, 1e-6);
  vec3 inscatter, transmittance, tableTransmittance;
  atmosphereToPoint(atmosphereView.camera.xyz, relative, sun, inscatter, transmittance);
  vec4 between;
  atmosphereAerial(v, distance, sun, between, tableTransmittance);
  results[4u * i] = vec4(inscatter, 0.0);
  results[4u * i + 1u] = vec4(transmittance, 0.0);
  results[4u * i + 2u] = vec4(atmospherePhased(between, dot(v, sun)), 0.0);
  results[4u * i + 3u] = vec4(tableTransmittance, 0.0);
}
