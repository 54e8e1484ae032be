#version 450
// The per-frame aerial perspective table (include/atmosphere_view.glsl): for every texel, the exact
// in-scattered light and transmittance from the camera to the point it stands for, from the
// precomputed tables [Bruneton & Neyret 2008]; then two texels of sky colours for the water's
// reflection: straight up and just above the horizon (averaged round it), tone-mapped linear.
// One dispatch before the terrain pass, so the terrain's vertices do one trilinear lookup instead
// of the ~40 table loads of the exact evaluation (docs/rendering.md, "Atmosphere").
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#define GLOBE_ATMOSPHERE_BINDING 0
#include "include/atmosphere.glsl"

layout(std140, set = 0, binding = 4) uniform AtmosphereViewBlock { AtmosphereViewGpu atmosphereView; };
layout(std430, set = 0, binding = 5) writeonly buffer AtmosphereViewTable { uvec4 atmosphereViewTable[]; };
#include "include/atmosphere_view.glsl"

uvec4 packFloats(vec3 v) { return uvec4(floatBitsToUint(v), 0u); }

// The sky's colour just above the horizon, averaged over four azimuths.
vec3 horizonSky(vec3 c, vec3 zenith, vec3 sun) {
  float r = length(c);
  float sinHorizon = atmBottom() / max(r, atmBottom());
  float mu = -sqrt(max(1.0 - sinHorizon * sinHorizon, 0.0)) + 0.02;
  vec3 east = normalize(abs(zenith.z) < 0.9 ? cross(vec3(0.0, 0.0, 1.0), zenith) : cross(vec3(1.0, 0.0, 0.0), zenith));
  vec3 north = cross(zenith, east);
  vec3 sum = vec3(0.0), transmittance;
  for (int k = 0; k < 4; ++k) {
    float a = float(k) * 0.5 * kAtmospherePi;
    vec3 level = cos(a) * east + sin(a) * north;
    sum += atmosphereSky(c, mu * zenith + sqrt(1.0 - mu * mu) * level, sun, transmittance);
  }
  return sum * 0.25;
}

void main() {
  uint index = gl_GlobalInvocationID.x;
  const uint texels = uint(GLOBE_VIEW_TEXELS);
  if (index >= texels + 2u) return;
  vec3 c = atmosphereView.camera.xyz;
  vec3 sun = atmosphereView.sun.xyz;
  if (index >= texels) {
    vec3 zenith = c / max(length(c), 1.0);
    vec3 transmittance;
    vec3 sky = index == texels ? atmosphereSky(c, zenith, sun, transmittance) : horizonSky(c, zenith, sun);
    atmosphereViewTable[index] = packFloats(atmosphereExposed(sky));
    return;
  }
  uvec3 i = uvec3(index % uint(GLOBE_VIEW_X), (index / uint(GLOBE_VIEW_X)) % uint(GLOBE_VIEW_Y),
                  index / uint(GLOBE_VIEW_X * GLOBE_VIEW_Y));
  vec3 xyz = vec3(i) / vec3(GLOBE_VIEW_X - 1, GLOBE_VIEW_Y - 1, GLOBE_VIEW_D - 1);
  vec3 v = atmosphereViewDirection(xyz.xy);
  vec4 between;
  vec3 transmittance;
  atmosphereBetween(c, v, atmosphereViewDistance(v, xyz.z), sun, between, transmittance);
  atmosphereViewTable[index] =
      uvec4(packHalf2x16(between.rg), packHalf2x16(between.ba), packHalf2x16(transmittance.rg),
            packHalf2x16(vec2(transmittance.b, 0.0)));
}
