// The atmosphere as the renderer uses it [Bruneton & Neyret 2008]: the sky along a view ray, the
// light between the camera and a point (aerial perspective), and the sun and sky light reaching a
// point, all from the precomputed tables (engine/atmosphere/atmosphere_luts.h). Camera-relative:
// positions are relative to the planet centre, the camera's computed in double on the CPU.
//
// The includer defines GLOBE_ATMOSPHERE_BINDING, the first of four bindings: the parameters
// (uniform) and the transmittance, irradiance and scattering tables.
//
// Conditions that depend on the camera alone (it is a push constant or uniform) are selects, never
// branches: lavapipe would compile the shader again at draw time (docs/rendering.md).
#ifndef GLOBE_ATMOSPHERE_GLSL
#define GLOBE_ATMOSPHERE_GLSL

#include "atmosphere_layout.h"

layout(std140, set = 0, binding = GLOBE_ATMOSPHERE_BINDING) uniform AtmosphereBlock { AtmosphereGpu atmosphere; };
layout(std430, set = 0, binding = GLOBE_ATMOSPHERE_BINDING + 1) readonly buffer AtmosphereTransmittance {
  vec4 atmosphereTransmittance[];
};
layout(std430, set = 0, binding = GLOBE_ATMOSPHERE_BINDING + 2) readonly buffer AtmosphereIrradiance {
  vec4 atmosphereIrradiance[];
};
layout(std430, set = 0, binding = GLOBE_ATMOSPHERE_BINDING + 3) readonly buffer AtmosphereScattering {
  vec4 atmosphereScattering[];
};

#define GLOBE_ATMOSPHERE atmosphere
#define GLOBE_TRANSMITTANCE_TEXEL(i) atmosphereTransmittance[i]
#define GLOBE_SCATTERING_TEXEL(i) atmosphereScattering[i]
#define GLOBE_IRRADIANCE_TEXEL(i) atmosphereIrradiance[i]
#include "atmosphere_model.glsl"

// Where the ray from `camera` along unit `v` enters the atmosphere (the camera itself when inside):
// xyz the point, w the distance to it; w < 0 when the ray misses the atmosphere. The impact
// parameter comes from a cross product, so nothing cancels for a far camera (1e11 m).
vec4 atmosphereEntry(vec3 camera, vec3 v) {
  float r = length(camera);
  float rmu = dot(camera, v);
  vec3 c = cross(camera, v);
  float discTop = atmTop() * atmTop() - dot(c, c);
  float entry = -rmu - atmSafeSqrt(discTop);
  bool outside = r > atmTop();
  bool misses = discTop < 0.0 || entry < 0.0;
  float along = mix(0.0, max(entry, 0.0), outside);
  return vec4(camera + v * along, mix(along, -1.0, outside && misses));
}

// (r, mu, mu_s, nu) of the ray along v from the point `p` (relative to the centre).
vec4 atmosphereRay(vec3 p, vec3 v, vec3 sun) {
  float r = atmClampRadius(length(p));
  float invLength = 1.0 / max(length(p), 1.0);
  return vec4(r, atmClampCos(dot(p, v) * invLength), atmClampCos(dot(p, sun) * invLength), atmClampCos(dot(v, sun)));
}

// In-scattered radiance from a combined scattering texel whose Mie part is already faded for a
// sun below the horizon (atmosphereMieFade), the phase functions applied.
vec3 atmospherePhased(vec4 combined, float nu) {
  return max(combined.rgb * atmRayleighPhase(nu) + atmSingleMie(combined) * atmMiePhase(nu), vec3(0.0));
}

// The reference's remedy for the Mie term's noise once the sun is below the horizon.
vec4 atmosphereMieFade(vec4 combined, float muS) { return vec4(combined.rgb, combined.a * smoothstep(0.0, 0.01, muS)); }

// In-scattered radiance from a combined scattering texel, the phase functions applied.
vec3 atmosphereInscatter(vec4 combined, float nu, float muS) {
  return atmospherePhased(atmosphereMieFade(combined, muS), nu);
}

// Sky radiance seen from `camera` along unit `v` (rays to the ground give the light scattered
// between the camera and the ground); `transmittance` to the top (0 through the ground).
vec3 atmosphereSky(vec3 camera, vec3 v, vec3 sun, out vec3 transmittance) {
  vec4 entry = atmosphereEntry(camera, v);
  vec4 ray = atmosphereRay(entry.xyz, v, sun);
  bool hitsGround = atmRayHitsGround(ray.x, ray.y);
  bool misses = entry.w < 0.0;
  transmittance = mix(atmTransmittanceToTop(ray.x, ray.y), vec3(float(misses)), bvec3(hitsGround || misses));
  vec3 radiance = atmosphereInscatter(atmScattering(ray.x, ray.y, ray.z, ray.w, hitsGround), ray.w, ray.z);
  return mix(radiance, vec3(0.0), bvec3(misses));
}

// The light between `camera` and the point `distance` along unit `v`: the in-scattered light as a
// combined texel without the phase functions (atmospherePhased), and the transmittance of what the
// point sends towards the camera.
void atmosphereBetween(vec3 camera, vec3 v, float distance, vec3 sun, out vec4 between, out vec3 transmittance) {
  vec4 entry = atmosphereEntry(camera, v);
  float d = max(distance - max(entry.w, 0.0), 0.0);  // the part of the segment inside the atmosphere
  vec4 ray = atmosphereRay(entry.xyz, v, sun);
  float r = ray.x, mu = ray.y, muS = ray.z, nu = ray.w;
  bool hitsGround = atmRayHitsGround(r, mu);
  transmittance = atmTransmittance(r, mu, d, hitsGround);
  float rp = atmClampRadius(sqrt(max(d * d + 2.0 * r * mu * d + r * r, 0.0)));
  float muP = atmClampCos((r * mu + d) / rp);
  float muSP = atmClampCos((r * muS + d * nu) / rp);
  vec4 near = atmScattering(r, mu, muS, nu, hitsGround);
  vec4 far = atmScattering(rp, muP, muSP, nu, hitsGround);
  between = atmosphereMieFade(max(near - vec4(transmittance, transmittance.r) * far, vec4(0.0)), muS);
  bool misses = entry.w < 0.0;
  between = mix(between, vec4(0.0), bvec4(misses));
  transmittance = mix(transmittance, vec3(1.0), bvec3(misses));
}

// The same with the phase functions applied, for the point camera + `relative` (the exact
// evaluation the per-frame table, atmosphere_view.glsl, stands in for).
void atmosphereToPoint(vec3 camera, vec3 relative, vec3 sun, out vec3 inscatter, out vec3 transmittance) {
  float distance = length(relative);
  vec3 v = relative / max(distance, 1e-6);
  vec4 between;
  atmosphereBetween(camera, v, distance, sun, between, transmittance);
  inscatter = atmospherePhased(between, dot(v, sun));
}

// Light on a surface point at `p` (relative to the centre) from the sun through the atmosphere
// (`sunLight`, on a plane facing the sun) and from the sky (`skyLight`, on a horizontal plane), both
// divided by pi, and `up` the local vertical: what surface_light.glsl lights a surface with.
void atmosphereSurfaceLight(vec3 p, vec3 sun, out vec3 sunLight, out vec3 skyLight, out vec3 up) {
  float r = length(p);
  up = p / max(r, 1.0);
  float muS = dot(up, sun);
  sunLight = atmosphere.sun.rgb * atmTransmittanceToSun(atmClampRadius(r), muS) * (1.0 / kAtmospherePi);
  skyLight = atmIrradiance(r, muS) * (1.0 / kAtmospherePi);
}

// Radiance -> scene value (display_encoding.glsl): misc.z is the planet's exposure over the sun's
// radiance, so that a white surface facing the sun above the air is 1.
vec3 atmosphereExposed(vec3 radiance) { return atmosphere.misc.z * radiance; }

#endif  // GLOBE_ATMOSPHERE_GLSL
