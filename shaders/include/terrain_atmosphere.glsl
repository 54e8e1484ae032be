// The terrain's colour through the atmosphere, per vertex (terrain_atmosphere.vert): sunlight
// attenuated on its way to the vertex, sky light, then aerial perspective (transmittance and
// in-scattered light between the camera and the vertex) from the per-frame table within 50 km
// (atmosphere_view.comp: one trilinear lookup, 8 texels, instead of the exact evaluation's ~40
// loads), exact beyond, tone-mapped. Per vertex, not per fragment: lavapipe's cost is per fragment
// (docs/rendering.md, "Atmosphere"). Bindings 3-8 follow the terrain's three (terrain_vertex.glsl).
//
// Within kNearAerial_m of the camera the air between is left out (a branch on the vertex's own
// distance, so lavapipe skips the lookup for whole batches of near vertices): at 300 m near sea
// level the in-scattered light is under 1 % of the sky's (2/255); it fades in up to twice that.
#define GLOBE_ATMOSPHERE_BINDING 3
#include "atmosphere.glsl"
#include "surface_light.glsl"

layout(std140, set = 0, binding = 7) uniform AtmosphereViewBlock { AtmosphereViewGpu atmosphereView; };
layout(std430, set = 0, binding = 8) readonly buffer AtmosphereViewTable { uvec4 atmosphereViewTable[]; };
#include "atmosphere_view.glsl"

const float kNearAerial_m = 300.0;

// The table at the point `distance` metres along unit `v`: in-scattered light (a combined texel,
// phases not applied) and transmittance, trilinear.
void atmosphereViewLookup(vec3 v, float distance, out vec4 between, out vec3 transmittance) {
  const uvec3 n = uvec3(GLOBE_VIEW_X, GLOBE_VIEW_Y, GLOBE_VIEW_D);
  vec3 p = atmosphereViewCoord(v, distance) * vec3(n - 1u);
  uvec3 i0 = min(uvec3(p), n - 2u);
  vec3 f = p - vec3(i0);
  between = vec4(0.0);
  transmittance = vec3(0.0);
  for (uint k = 0u; k < 8u; ++k) {
    uvec3 corner = uvec3(k & 1u, (k >> 1u) & 1u, k >> 2u);
    vec3 w3 = mix(1.0 - f, f, vec3(corner));
    float w = w3.x * w3.y * w3.z;
    uvec4 texel = atmosphereViewTable[atmosphereViewIndex(i0 + corner)];
    between += w * vec4(unpackHalf2x16(texel.x), unpackHalf2x16(texel.y));
    transmittance += w * vec3(unpackHalf2x16(texel.z), unpackHalf2x16(texel.w).x);
  }
}

// The air between the camera and the point `distance` metres along unit `v`: from the table within
// its reach, beyond it the exact evaluation (a branch on the vertex's own distance).
void atmosphereAerial(vec3 v, float distance, vec3 sun, out vec4 between, out vec3 transmittance) {
  if (distance < kAtmosphereViewFar_m) {
    atmosphereViewLookup(v, distance, between, transmittance);
  } else {
    atmosphereBetween(atmosphereView.camera.xyz, v, distance, sun, between, transmittance);
  }
}

// What the water's fragments (terrain_water.frag) need to put their own colour through the same air.
struct TerrainAerial {
  vec3 transmittance;  // of the air between the camera and the vertex
  vec3 inscatter;      // the in-scattered light between, exposed: a scene value c becomes c T + inscatter
  // What a normal-mapped fragment needs to light itself (atmosphereSurfaceLight): the sun's and the
  // sky's light times exposure and transmittance, so that its scene value is albedo *
  // surfaceLight(n, ...) + inscatter; and the local vertical.
  vec3 sunLight;
  vec3 skyLight;
  vec3 up;
};

// The scene value (display_encoding.glsl) of a surface point of `albedo` and unit normal `n` at `relative` (metres from
// the camera, planet-fixed axes), lit by the sun in direction `sun`.
vec3 terrainAtmosphereColour(vec3 albedo, vec3 n, vec3 relative, vec3 sun, out TerrainAerial aerial) {
  vec3 camera = atmosphereView.camera.xyz;
  vec3 sunLight, skyLight, up;
  atmosphereSurfaceLight(camera + relative, sun, sunLight, skyLight, up);
  vec3 radiance = albedo * surfaceLight(n, sun, up, sunLight, skyLight);
  vec3 inscatter = vec3(0.0), transmittance = vec3(1.0);
  float distance = length(relative);
  if (distance > kNearAerial_m) {
    vec3 v = relative / distance;
    vec4 between;
    atmosphereAerial(v, distance, sun, between, transmittance);
    float fade = smoothstep(kNearAerial_m, 2.0 * kNearAerial_m, distance);
    inscatter = atmospherePhased(between, dot(v, sun)) * fade;
    transmittance = mix(vec3(1.0), transmittance, fade);
  }
  aerial.transmittance = transmittance;
  aerial.inscatter = atmosphereExposed(inscatter);
  aerial.sunLight = atmosphere.misc.z * transmittance * sunLight;
  aerial.skyLight = atmosphere.misc.z * transmittance * skyLight;
  aerial.up = up;
  return atmosphereExposed(radiance * transmittance + inscatter);
}
