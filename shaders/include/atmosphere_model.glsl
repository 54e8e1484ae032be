// The atmosphere model of [Bruneton & Neyret 2008] (docs/rendering.md, "Atmosphere"): geometry of
// rays in a spherical shell, density profiles, phase functions, the mapping between table texels
// and (r, mu, mu_s, nu), and the interpolated lookups. Shared by the precomputation kernel and the
// renderer's shaders. All lengths in metres, floats.
//
// The includer defines, before including:
//   GLOBE_ATMOSPHERE                 an AtmosphereGpu value (atmosphere_layout.h)
//   GLOBE_TRANSMITTANCE_TEXEL(i)     vec4 texel i of the transmittance table
//   GLOBE_SCATTERING_TEXEL(i)        vec4 texel i of the scattering table (or of a delta table)
//   GLOBE_IRRADIANCE_TEXEL(i)        vec4 texel i of the irradiance table
// r: distance from the planet centre; mu: cosine of the ray's angle to the zenith; mu_s: of the sun's;
// nu: cosine between the ray and the sun.
#ifndef GLOBE_ATMOSPHERE_MODEL_GLSL
#define GLOBE_ATMOSPHERE_MODEL_GLSL

#include "atmosphere_layout.h"
#include "atmosphere_phase.glsl"

float atmBottom() { return GLOBE_ATMOSPHERE.radii.x; }
float atmTop() { return GLOBE_ATMOSPHERE.radii.y; }
float atmMuSMin() { return GLOBE_ATMOSPHERE.radii.z; }
// sqrt(top^2 - bottom^2): the horizon ray's length from the ground to the top.
float atmHorizon() { return sqrt((atmTop() - atmBottom()) * (atmTop() + atmBottom())); }

float atmSafeSqrt(float a) { return sqrt(max(a, 0.0)); }
float atmClampCos(float mu) { return clamp(mu, -1.0, 1.0); }
float atmClampRadius(float r) { return clamp(r, atmBottom(), atmTop()); }

// Distances along the ray (r, mu) to the top and to the ground sphere. The discriminants are
// written as (a - b)(a + b) + (r mu)^2 so that nothing cancels near the ground.
float atmDistanceToTop(float r, float mu) {
  float disc = (atmTop() - r) * (atmTop() + r) + (r * mu) * (r * mu);
  return max(-r * mu + atmSafeSqrt(disc), 0.0);
}
float atmDistanceToBottom(float r, float mu) {
  float disc = (r * mu) * (r * mu) - (r - atmBottom()) * (r + atmBottom());
  return max(-r * mu - atmSafeSqrt(disc), 0.0);
}
bool atmRayHitsGround(float r, float mu) {
  return mu < 0.0 && (r * mu) * (r * mu) - (r - atmBottom()) * (r + atmBottom()) >= 0.0;
}
float atmDistanceToBoundary(float r, float mu, bool hitsGround) {
  return hitsGround ? atmDistanceToBottom(r, mu) : atmDistanceToTop(r, mu);
}

// Density profiles, 0..1, at `altitude` metres above the bottom.
float atmRayleighDensity(float altitude) { return min(exp(-altitude / GLOBE_ATMOSPHERE.rayleigh.w), 1.0); }
float atmMieDensity(float altitude) { return min(exp(-altitude / GLOBE_ATMOSPHERE.mieScattering.w), 1.0); }
float atmOzoneDensity(float altitude) {
  return max(1.0 - abs(altitude - GLOBE_ATMOSPHERE.ozone.w) / GLOBE_ATMOSPHERE.misc.x, 0.0);
}

float atmMiePhase(float nu) { return atmCornetteShanksPhase(nu, GLOBE_ATMOSPHERE.mieExtinction.w); }

// [0, 1] -> texel centres of an n-texel axis, and back.
float atmToTexel(float x, float n) { return 0.5 / n + x * (1.0 - 1.0 / n); }
float atmFromTexel(float u, float n) { return (u - 0.5 / n) / (1.0 - 1.0 / n); }

// ---- Transmittance table: (x_mu, x_r) from the distance to the top and the horizon distance rho.
vec2 atmTransmittanceUv(float r, float mu) {
  float H = atmHorizon();
  float rho = atmSafeSqrt((r - atmBottom()) * (r + atmBottom()));
  float d = atmDistanceToTop(r, mu);
  float dMin = atmTop() - r, dMax = rho + H;
  float xMu = (d - dMin) / max(dMax - dMin, 1e-3);
  return vec2(atmToTexel(clamp(xMu, 0.0, 1.0), float(GLOBE_TRANSMITTANCE_W)),
              atmToTexel(clamp(rho / H, 0.0, 1.0), float(GLOBE_TRANSMITTANCE_H)));
}
// The inverse: (r, mu) of a texel's uv.
vec2 atmTransmittanceRMu(vec2 uv) {
  float H = atmHorizon();
  float rho = H * atmFromTexel(uv.y, float(GLOBE_TRANSMITTANCE_H));
  float r = sqrt(rho * rho + atmBottom() * atmBottom());
  float dMin = atmTop() - r, dMax = rho + H;
  float d = dMin + atmFromTexel(uv.x, float(GLOBE_TRANSMITTANCE_W)) * (dMax - dMin);
  float mu = d == 0.0 ? 1.0 : (H * H - rho * rho - d * d) / (2.0 * r * d);
  return vec2(r, atmClampCos(mu));
}

// Bilinear lookup of a w x h table at texel-centred uv.
#define GLOBE_ATM_BILINEAR(FETCH, uv, w, h)                                              \
  {                                                                                      \
    vec2 p = clamp((uv) * vec2(w, h) - 0.5, vec2(0.0), vec2(float(w) - 1.0, float(h) - 1.0)); \
    uvec2 i0 = uvec2(p);                                                                 \
    uvec2 i1 = min(i0 + 1u, uvec2(w - 1, h - 1));                                        \
    vec2 f = p - vec2(i0);                                                               \
    vec4 a = mix(FETCH(i0.y * uint(w) + i0.x), FETCH(i0.y * uint(w) + i1.x), f.x);       \
    vec4 b = mix(FETCH(i1.y * uint(w) + i0.x), FETCH(i1.y * uint(w) + i1.x), f.x);       \
    return mix(a, b, f.y);                                                               \
  }

vec4 atmTransmittanceLookup(vec2 uv) {
  GLOBE_ATM_BILINEAR(GLOBE_TRANSMITTANCE_TEXEL, uv, GLOBE_TRANSMITTANCE_W, GLOBE_TRANSMITTANCE_H)
}
vec4 atmIrradianceLookup(vec2 uv) {
  GLOBE_ATM_BILINEAR(GLOBE_IRRADIANCE_TEXEL, uv, GLOBE_IRRADIANCE_W, GLOBE_IRRADIANCE_H)
}

// Transmittance from (r, mu) to the top of the atmosphere (the ray must not hit the ground).
vec3 atmTransmittanceToTop(float r, float mu) {
  return atmTransmittanceLookup(atmTransmittanceUv(atmClampRadius(r), mu)).rgb;
}

// Transmittance between the point (r, mu) and the point d further along the ray.
vec3 atmTransmittance(float r, float mu, float d, bool hitsGround) {
  float rd = atmClampRadius(sqrt(d * d + 2.0 * r * mu * d + r * r));
  float mud = atmClampCos((r * mu + d) / rd);
  vec3 a = hitsGround ? atmTransmittanceToTop(rd, -mud) : atmTransmittanceToTop(r, mu);
  vec3 b = hitsGround ? atmTransmittanceToTop(r, -mu) : atmTransmittanceToTop(rd, mud);
  return min(a / max(b, vec3(1e-30)), vec3(1.0));
}

// Transmittance towards the sun, its disc partly below the horizon fading out.
vec3 atmTransmittanceToSun(float r, float muS) {
  float sinH = atmBottom() / r;
  float cosH = -atmSafeSqrt(1.0 - sinH * sinH);
  float alpha = GLOBE_ATMOSPHERE.sun.w;
  return atmTransmittanceToTop(r, muS) * smoothstep(-sinH * alpha, sinH * alpha, muS - cosH);
}

// ---- Irradiance table: (mu_s, altitude), both linear.
vec2 atmIrradianceUv(float r, float muS) {
  float xR = (r - atmBottom()) / (atmTop() - atmBottom());
  return vec2(atmToTexel(muS * 0.5 + 0.5, float(GLOBE_IRRADIANCE_W)),
              atmToTexel(clamp(xR, 0.0, 1.0), float(GLOBE_IRRADIANCE_H)));
}
vec2 atmIrradianceRMuS(vec2 uv) {
  float xMuS = atmFromTexel(uv.x, float(GLOBE_IRRADIANCE_W));
  float xR = atmFromTexel(uv.y, float(GLOBE_IRRADIANCE_H));
  return vec2(atmBottom() + xR * (atmTop() - atmBottom()), atmClampCos(2.0 * xMuS - 1.0));
}
vec3 atmIrradiance(float r, float muS) { return atmIrradianceLookup(atmIrradianceUv(atmClampRadius(r), muS)).rgb; }

// ---- Scattering table: (u_nu, u_mu_s, u_mu, u_r). Rays that hit the ground use the lower half of
// the mu axis, the others the upper half, each mapped by the distance to the boundary.
vec4 atmScatteringUvwz(float r, float mu, float muS, float nu, bool hitsGround) {
  float H = atmHorizon();
  float rho = atmSafeSqrt((r - atmBottom()) * (r + atmBottom()));
  float uR = atmToTexel(rho / H, float(GLOBE_SCATTERING_R));
  float rmu = r * mu;
  float disc = rmu * rmu - (r - atmBottom()) * (r + atmBottom());
  float halfMu = float(GLOBE_SCATTERING_MU / 2);
  float dG = -rmu - atmSafeSqrt(disc), dGMin = r - atmBottom(), dGMax = rho;
  float uGround = 0.5 - 0.5 * atmToTexel(dGMax == dGMin ? 0.0 : clamp((dG - dGMin) / (dGMax - dGMin), 0.0, 1.0), halfMu);
  float dT = -rmu + atmSafeSqrt(disc + H * H), dTMin = atmTop() - r, dTMax = rho + H;
  float uSky = 0.5 + 0.5 * atmToTexel(clamp((dT - dTMin) / max(dTMax - dTMin, 1e-3), 0.0, 1.0), halfMu);
  float uMu = hitsGround ? uGround : uSky;
  float d = atmDistanceToTop(atmBottom(), muS);
  float dMin = atmTop() - atmBottom(), dMax = H;
  float a = (d - dMin) / (dMax - dMin);
  float A = (atmDistanceToTop(atmBottom(), atmMuSMin()) - dMin) / (dMax - dMin);
  float uMuS = atmToTexel(max(1.0 - a / A, 0.0) / (1.0 + a), float(GLOBE_SCATTERING_MU_S));
  return vec4((nu + 1.0) * 0.5, uMuS, uMu, uR);
}

// One nu slice, trilinear over (mu_s, mu, r).
vec4 atmScatteringSlice(uint nuIndex, vec3 uvw) {
  const uvec3 n = uvec3(GLOBE_SCATTERING_MU_S, GLOBE_SCATTERING_MU, GLOBE_SCATTERING_R);
  vec3 p = clamp(uvw * vec3(n) - 0.5, vec3(0.0), vec3(n) - 1.0);
  uvec3 i0 = uvec3(p);
  uvec3 i1 = min(i0 + 1u, n - 1u);
  vec3 f = p - vec3(i0);
  const uint NU = uint(GLOBE_SCATTERING_NU);
#define GLOBE_ATM_AT(MUS_, MU_, R_) GLOBE_SCATTERING_TEXEL((((R_) * n.y + (MU_)) * n.x + (MUS_)) * NU + nuIndex)
  vec4 c00 = mix(GLOBE_ATM_AT(i0.x, i0.y, i0.z), GLOBE_ATM_AT(i1.x, i0.y, i0.z), f.x);
  vec4 c10 = mix(GLOBE_ATM_AT(i0.x, i1.y, i0.z), GLOBE_ATM_AT(i1.x, i1.y, i0.z), f.x);
  vec4 c01 = mix(GLOBE_ATM_AT(i0.x, i0.y, i1.z), GLOBE_ATM_AT(i1.x, i0.y, i1.z), f.x);
  vec4 c11 = mix(GLOBE_ATM_AT(i0.x, i1.y, i1.z), GLOBE_ATM_AT(i1.x, i1.y, i1.z), f.x);
#undef GLOBE_ATM_AT
  return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

// The scattering table at (r, mu, mu_s, nu), interpolated in all four.
vec4 atmScattering(float r, float mu, float muS, float nu, bool hitsGround) {
  vec4 u = atmScatteringUvwz(atmClampRadius(r), mu, muS, nu, hitsGround);
  float x = u.x * float(GLOBE_SCATTERING_NU - 1);
  uint i0 = min(uint(x), uint(GLOBE_SCATTERING_NU - 2));
  float f = clamp(x - float(i0), 0.0, 1.0);
  return mix(atmScatteringSlice(i0, u.yzw), atmScatteringSlice(i0 + 1u, u.yzw), f);
}

// Single Mie scattering's rgb from the table's combined texel (its red in alpha): scaled by the
// Rayleigh part's colour, as if Mie and Rayleigh light had come through the same path.
vec3 atmSingleMie(vec4 combined) {
  vec3 rayleigh = GLOBE_ATMOSPHERE.rayleigh.rgb, mie = GLOBE_ATMOSPHERE.mieScattering.rgb;
  vec3 ratio = combined.rgb / max(combined.r, 1e-30) * (rayleigh.r / max(rayleigh, vec3(1e-30))) *
               (mie / max(mie.r, 1e-30));
  return combined.a * mix(mie / max(mie.r, 1e-30), ratio, bvec3(combined.r > 1e-30 && rayleigh.r > 0.0));
}

#endif  // GLOBE_ATMOSPHERE_MODEL_GLSL
