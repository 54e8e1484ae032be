// The analytic haze of the terrain pipelines without the atmosphere's light (the `sky` detail of
// `fast` and `balanced`; docs/rendering.md, "Haze"): the transmittance T and the in-scattered light
// S between the camera and a vertex, so that a scene value c reaches the camera as c T + S, as
// `full`'s aerial perspective does from the tables (terrain_atmosphere.glsl). Per vertex and without
// a table read: `full`'s table reads and its per-frame table cost it about half its extra time each.
//
// T: the optical depth of the Rayleigh and Mie densities (exponential in altitude) along the ray,
// exact for heights linear along each of kHazeSegments pieces, the heights taken on the curved ray
// from the vertex's own elevation (no cancellation against the planet's radius, even from 1e11 m).
// S: the sunlight of the frame (the sun's light through the air over the ground below the camera:
// for Mie at the ground, for Rayleigh at the mean height of its scattering between the ground and
// the camera, whiter at a low sun), scattered once by the two media mixed as along the ray, plus the sky's and the ground's light,
// taken as the same from every direction, scattered once (what the sky's many orders of scattering
// add, bluest at dusk): a stretch of air sends towards the camera its scattering coefficient times
// the phase function times the light, so the whole ray sends (phase-weighted share of scattering in
// extinction) x light x (1 - T). Zero constants (no atmosphere, or the atmosphere off) give T = 1, S = 0.
//
// The includer declares the frame constants (TerrainFrameBlock, terrain_layout.h).
#ifndef GLOBE_TERRAIN_HAZE_GLSL
#define GLOBE_TERRAIN_HAZE_GLSL

#include "atmosphere_phase.glsl"
#include "surface_light.glsl"

const int kHazeSegments = 4;

// The integral of exp(-k h) over a piece of ray `length` metres long along which the height goes
// linearly from `a` to `b` metres.
float hazeDepth(float a, float b, float k, float length) {
  float x = (b - a) * k;
  float share = abs(x) < 1e-3 ? 1.0 - 0.5 * x : (1.0 - exp(-x)) / x;
  return length * exp(-a * k) * share;
}

// T and S (scene units) between the camera and the point `relative` metres from it (planet-fixed
// axes) at `elevation_m` above the planet's radius.
void terrainHaze(vec3 relative, float elevation_m, out vec3 transmittance, out vec3 inscatter) {
  float distance = length(relative);
  vec3 toCamera = -relative / max(distance, 1e-6);
  vec3 up = normalize(relative - frame.centreFromCamera.xyz);
  float r = frame.planetCentre.w + elevation_m, mu = dot(up, toCamera), top = frame.hazeSun.w;
  // Back from the point towards the camera, up to where the ray leaves the air.
  float exit = -r * mu + sqrt(max(r * r * mu * mu - (r - top) * (r + top), 0.0));
  float piece = min(distance, max(exit, 0.0)) / float(kHazeSegments);
  float kR = frame.hazeRayleigh.w, kM = frame.hazeMie.w;
  float h0 = elevation_m, tauR = 0.0, tauM = 0.0;
  for (int i = 1; i <= kHazeSegments; ++i) {
    float t = piece * float(i);
    float h1 = sqrt(r * r + t * (2.0 * r * mu + t)) - frame.planetCentre.w;
    tauR += hazeDepth(h0, h1, kR, piece);
    tauM += hazeDepth(h0, h1, kM, piece);
    h0 = h1;
  }
  vec3 rayleigh = frame.hazeRayleigh.rgb * tauR, mie = frame.hazeMie.rgb * tauM;
  transmittance = exp(-(rayleigh + mie));
  float nu = -dot(toCamera, frame.sun.xyz);
  float phaseR = atmRayleighPhase(nu), phaseM = atmCornetteShanksPhase(nu, frame.hazeMieScattering.w);
  vec3 mieScattered = frame.hazeMieScattering.rgb * tauM;
  vec3 scattered = frame.hazeSunAloft.rgb * rayleigh * phaseR + frame.hazeSun.rgb * mieScattered * phaseM +
                   frame.hazeSky.rgb * (rayleigh + mieScattered);
  inscatter = scattered / max(rayleigh + mie, vec3(1e-9)) * (1.0 - transmittance);
}

// The light on ground of unit normal `n` (`sun`, `up`: the sun's direction and the local vertical, in
// the same frame), `sunShare` of the sun's reaching it: through the air, the sun's and the sky's light
// over the ground below the camera (the frame's constants), with surfaceLight as `full` lights from
// its tables per vertex, so that the presets' ground is lit alike (reddened and dimmed by the air at
// dusk, blue in the shade); without air, a white sun and the frame's ambient light. Both, then a
// select: no branch on a frame constant (docs/rendering.md, "No shader compile per frame").
vec3 hazeGroundLight(vec3 n, vec3 sun, vec3 up, float sunShare) {
  const float kPi = 3.14159265358979;
  vec3 air = surfaceLight(n, sun, up, frame.hazeSun.rgb * (sunShare / kPi), frame.hazeGround.rgb);
  float white = frame.sun.w + (1.0 - frame.sun.w) * max(dot(n, sun), 0.0) * sunShare;
  return mix(vec3(white), air, bvec3(frame.hazeGround.w > 0.5));
}

#endif  // GLOBE_TERRAIN_HAZE_GLSL
