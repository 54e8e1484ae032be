// The per-frame aerial perspective table's coordinates (atmosphere_layout.h, GLOBE_VIEW_*): a
// screen direction (NDC x, y within +-GLOBE_VIEW_EXTENT, from the camera's own axes, so off-screen
// vertices of visible triangles clamp to the border) and the distance along that ray. The distance
// axis spans, per direction, only where terrain can be (atmosphereViewSegment): both ends are
// continuous in the direction, also across the horizon, so texels of neighbouring directions at
// the same coordinate stand for nearby distances. Logarithmically spaced beyond
// kAtmosphereViewNear_m, so that the near kilometres, where most vertices are, get as many texels
// as the far thousand. Shared by
// atmosphere_view.comp (which fills the table with the exact evaluation) and the terrain's vertex
// stage (which reads it).
//
// The includer declares `atmosphereView` (AtmosphereViewGpu) first.
#ifndef GLOBE_ATMOSPHERE_VIEW_GLSL
#define GLOBE_ATMOSPHERE_VIEW_GLSL

#include "atmosphere_layout.h"

const float kAtmosphereViewNear_m = 500.0;
// The table's reach (metres): terrain farther away is evaluated exactly per vertex (few vertices,
// the levels of detail coarsen with distance; and the table's rows would span too much there).
const float kAtmosphereViewFar_m = 50000.0;

// [t0, t1]: the stretch of the ray along unit `v` from the camera where terrain can be (metres):
// from where it enters the sphere of the highest terrain (or the camera) to where it leaves it,
// less the chord through the sphere of the lowest when it goes down into that; at most
// kAtmosphereViewFar_m long. The impact
// parameter comes from a cross product and the discriminants are factored, so neither a far camera
// (1e11 m) nor a grazing ray cancels.
vec2 atmosphereViewSegment(vec3 v) {
  vec3 c = atmosphereView.camera.xyz;
  float lowest = atmosphereView.terrain.x, highest = atmosphereView.terrain.y;
  vec3 offAxis = cross(c, v);
  float impact = sqrt(dot(offAxis, offAxis));
  float along = -dot(c, v);  // to the ray's closest point to the centre
  float outer = sqrt(max((highest - impact) * (highest + impact), 0.0));
  float inner = sqrt(max((lowest - impact) * (lowest + impact), 0.0));
  bool above = dot(c, c) > highest * highest;
  float t0 = mix(0.0, max(along - outer, 0.0), above);
  float t1 = along + outer - 2.0 * inner * step(0.0, along);
  return vec2(t0, clamp(t1, t0 + 1.0, t0 + kAtmosphereViewFar_m));
}

// Table coordinates in [0, 1]^3 of the point `distance` metres along unit `v`.
vec3 atmosphereViewCoord(vec3 v, float distance) {
  float depth = max(dot(v, atmosphereView.forward.xyz), 1e-6);
  vec2 ndc = vec2(dot(v, atmosphereView.right.xyz) / atmosphereView.right.w,
                  -dot(v, atmosphereView.up.xyz) / atmosphereView.up.w) / depth;
  vec2 segment = atmosphereViewSegment(v);
  float along = log(1.0 + max(distance - segment.x, 0.0) / kAtmosphereViewNear_m) /
                log(1.0 + (segment.y - segment.x) / kAtmosphereViewNear_m);
  return clamp(vec3(ndc / (2.0 * GLOBE_VIEW_EXTENT) + 0.5, along), 0.0, 1.0);
}

// The inverse, for the table's texels: unit direction of screen coordinates `xy`.
vec3 atmosphereViewDirection(vec2 xy) {
  vec2 ndc = (xy - 0.5) * (2.0 * GLOBE_VIEW_EXTENT);
  vec3 ray = atmosphereView.forward.xyz + ndc.x * atmosphereView.right.w * atmosphereView.right.xyz -
             ndc.y * atmosphereView.up.w * atmosphereView.up.xyz;
  return normalize(ray);
}

// The distance (metres) of table coordinate `along` on the ray along unit `v`.
float atmosphereViewDistance(vec3 v, float along) {
  vec2 segment = atmosphereViewSegment(v);
  return segment.x + kAtmosphereViewNear_m * (exp(along * log(1.0 + (segment.y - segment.x) / kAtmosphereViewNear_m)) - 1.0);
}

// Texel index of integer table coordinates.
uint atmosphereViewIndex(uvec3 i) { return (i.z * uint(GLOBE_VIEW_Y) + i.y) * uint(GLOBE_VIEW_X) + i.x; }

#endif  // GLOBE_ATMOSPHERE_VIEW_GLSL
