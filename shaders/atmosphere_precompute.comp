#version 450
// Precomputed atmospheric scattering [Bruneton & Neyret 2008]: one step of the tables' computation
// per pipeline (specialization constant 0, GLOBE_ATMOSPHERE_* in include/atmosphere_layout.h), run
// once at start by engine/atmosphere/atmosphere_luts.cpp in this order:
//   transmittance; direct irradiance (-> delta irradiance); single scattering (-> delta Rayleigh,
//   delta Mie, scattering); then for each order 2..kOrders: scattering density (-> delta density),
//   indirect irradiance of the order before (-> delta irradiance, irradiance +=), multiple
//   scattering (-> delta multiple, scattering +=).
// Specialization constant 1: the order before is single scattering (its Rayleigh and Mie deltas
// still need their phase functions), else a multiple-scattering delta (phase already in it).
// Loop bounds are constants (docs/rendering.md: no control flow on push constants).
#extension GL_GOOGLE_include_directive : require

layout(constant_id = 0) const uint kStep = 0u;
layout(constant_id = 1) const bool kFirstOrder = true;
layout(local_size_x = 64) in;

#include "include/atmosphere_layout.h"

layout(std140, set = 0, binding = 0) uniform AtmosphereBlock { AtmosphereGpu atmosphere; };
layout(std430, set = 0, binding = 1) buffer TransmittanceTable { vec4 transmittance[]; };
layout(std430, set = 0, binding = 2) buffer IrradianceTable { vec4 irradiance[]; };
layout(std430, set = 0, binding = 3) buffer DeltaIrradianceTable { vec4 deltaIrradiance[]; };
layout(std430, set = 0, binding = 4) buffer ScatteringTable { vec4 scattering[]; };
// Three 4D tables one after the other: delta Rayleigh (also delta multiple), delta Mie, delta density.
layout(std430, set = 0, binding = 5) buffer DeltaTables { vec4 deltas[]; };

const uint kDeltaRayleigh = 0u;
const uint kDeltaMie = uint(GLOBE_SCATTERING_TEXELS);
const uint kDeltaDensity = 2u * uint(GLOBE_SCATTERING_TEXELS);
uint deltaBase = 0u;  // which delta table the model's scattering lookups read

#define GLOBE_ATMOSPHERE atmosphere
#define GLOBE_TRANSMITTANCE_TEXEL(i) transmittance[i]
#define GLOBE_SCATTERING_TEXEL(i) deltas[deltaBase + (i)]
#define GLOBE_IRRADIANCE_TEXEL(i) deltaIrradiance[i]
#include "include/atmosphere_model.glsl"

const int kTransmittanceSteps = 250;
const int kScatteringSteps = 50;
const int kSphereTheta = 6;  // directions of the density and irradiance integrals
const int kSpherePhi = 12;

// Trapezoid weight of sample i of 0..n.
float trapezoid(int i, int n) { return (i == 0 || i == n) ? 0.5 : 1.0; }

// Sample i of 0..n along a ray of `length` metres, closer together where the air is dense: near the
// start of rays that leave the ground or go up, near the end of rays that hit the ground (Mie's
// 1.2 km scale height is missed by even steps over a 600 km ray). x: distance; y: trapezoid weight.
vec2 raySample(int i, int n, float length, bool hitsGround) {
  float s0 = float(max(i - 1, 0)) / float(n), s = float(i) / float(n), s1 = float(min(i + 1, n)) / float(n);
  vec3 q = hitsGround ? 1.0 - (1.0 - vec3(s0, s, s1)) * (1.0 - vec3(s0, s, s1)) : vec3(s0, s, s1) * vec3(s0, s, s1);
  return vec2(q.y, 0.5 * (q.z - q.x)) * length;
}

vec3 extinctionAt(float altitude) {
  return atmosphere.rayleigh.rgb * atmRayleighDensity(altitude) +
         atmosphere.mieExtinction.rgb * atmMieDensity(altitude) + atmosphere.ozone.rgb * atmOzoneDensity(altitude);
}

vec3 computeTransmittance(float r, float mu) {
  float dx = atmDistanceToTop(r, mu) / float(kTransmittanceSteps);
  vec3 depth = vec3(0.0);
  for (int i = 0; i <= kTransmittanceSteps; ++i) {
    float d = float(i) * dx;
    float rd = sqrt(d * d + 2.0 * r * mu * d + r * r);
    depth += extinctionAt(rd - atmBottom()) * trapezoid(i, kTransmittanceSteps);
  }
  return exp(-depth * dx);
}

// The 4D table texel `index`'s (r, mu, mu_s, nu); .w of the result is nu, hitsGround returned.
vec4 scatteringTexelParameters(uint index, out bool hitsGround) {
  const uint NU = uint(GLOBE_SCATTERING_NU), MUS = uint(GLOBE_SCATTERING_MU_S), MU = uint(GLOBE_SCATTERING_MU);
  uint iNu = index % NU, iMuS = (index / NU) % MUS, iMu = (index / (NU * MUS)) % MU, iR = index / (NU * MUS * MU);
  float H = atmHorizon();
  float rho = H * atmFromTexel((float(iR) + 0.5) / float(GLOBE_SCATTERING_R), float(GLOBE_SCATTERING_R));
  float r = sqrt(rho * rho + atmBottom() * atmBottom());
  float uMu = (float(iMu) + 0.5) / float(MU);
  float halfMu = float(MU / 2u);
  hitsGround = iMu < MU / 2u;
  float mu;
  if (hitsGround) {
    float dMin = r - atmBottom(), dMax = rho;
    float d = dMin + (dMax - dMin) * atmFromTexel(1.0 - 2.0 * uMu, halfMu);
    mu = d == 0.0 ? -1.0 : atmClampCos(-(rho * rho + d * d) / (2.0 * r * d));
  } else {
    float dMin = atmTop() - r, dMax = rho + H;
    float d = dMin + (dMax - dMin) * atmFromTexel(2.0 * uMu - 1.0, halfMu);
    mu = d == 0.0 ? 1.0 : atmClampCos((H * H - rho * rho - d * d) / (2.0 * r * d));
  }
  float xMuS = atmFromTexel((float(iMuS) + 0.5) / float(MUS), float(MUS));
  float dMin = atmTop() - atmBottom(), dMax = H;
  float A = (atmDistanceToTop(atmBottom(), atmMuSMin()) - dMin) / (dMax - dMin);
  float a = (A - xMuS * A) / (1.0 + xMuS * A);
  float d = dMin + min(a, A) * (dMax - dMin);
  float muS = d == 0.0 ? 1.0 : atmClampCos((H * H - d * d) / (2.0 * atmBottom() * d));
  float nu = -1.0 + 2.0 * float(iNu) / float(NU - 1u);
  float spread = sqrt(max((1.0 - mu * mu) * (1.0 - muS * muS), 0.0));
  return vec4(r, mu, muS, clamp(nu, mu * muS - spread, mu * muS + spread));
}

void computeSingleScattering(vec4 p, bool hitsGround, out vec3 rayleigh, out vec3 mie) {
  float r = p.x, mu = p.y, muS = p.z, nu = p.w;
  float length = atmDistanceToBoundary(r, mu, hitsGround);
  rayleigh = vec3(0.0);
  mie = vec3(0.0);
  for (int i = 0; i <= kScatteringSteps; ++i) {
    vec2 step = raySample(i, kScatteringSteps, length, hitsGround);
    float d = step.x;
    float rd = atmClampRadius(sqrt(d * d + 2.0 * r * mu * d + r * r));
    float muSd = atmClampCos((r * muS + d * nu) / rd);
    vec3 t = atmTransmittance(r, mu, d, hitsGround) * atmTransmittanceToSun(rd, muSd) * step.y;
    rayleigh += t * atmRayleighDensity(rd - atmBottom());
    mie += t * atmMieDensity(rd - atmBottom());
  }
  rayleigh *= atmosphere.sun.rgb * atmosphere.rayleigh.rgb;
  mie *= atmosphere.sun.rgb * atmosphere.mieScattering.rgb;
}

// The previous order's radiance arriving along (r, mu) for every nu sample of the tables: one
// trilinear lookup per nu slice, shared by all the directions of a cone of constant mu (only nu
// changes round it). Single scattering keeps Rayleigh (rgb) and Mie (rgb) apart for their phases.
const int NU = GLOBE_SCATTERING_NU;
void previousOrderSlices(float r, float mu, float muS, bool hitsGround, out vec3 rayleigh[NU], out vec3 mie[NU]) {
  vec3 uvw = atmScatteringUvwz(atmClampRadius(r), mu, muS, 0.0, hitsGround).yzw;
  for (int k = 0; k < NU; ++k) {
    deltaBase = kDeltaRayleigh;  // single Rayleigh, or the multiple-scattering delta
    rayleigh[k] = atmScatteringSlice(uint(k), uvw).rgb;
    deltaBase = kDeltaMie;
    mie[k] = kFirstOrder ? atmScatteringSlice(uint(k), uvw).rgb : vec3(0.0);
  }
}

// Radiance arriving along a direction at `nu` from the sun, from the slices above.
vec3 previousOrderAt(float nu, vec3 rayleigh[NU], vec3 mie[NU]) {
  float x = (nu + 1.0) * 0.5 * float(NU - 1);
  int i0 = min(int(x), NU - 2);
  float f = clamp(x - float(i0), 0.0, 1.0);
  vec3 r = mix(rayleigh[i0], rayleigh[i0 + 1], f);
  vec3 m = mix(mie[i0], mie[i0 + 1], f);
  return kFirstOrder ? r * atmRayleighPhase(nu) + m * atmMiePhase(nu) : r;
}

vec3 computeScatteringDensity(vec4 p) {
  float r = p.x, mu = p.y, muS = p.z, nu = p.w;
  vec3 omega = vec3(sqrt(max(1.0 - mu * mu, 0.0)), 0.0, mu);
  float sunX = omega.x == 0.0 ? 0.0 : (nu - mu * muS) / omega.x;
  vec3 omegaS = vec3(sunX, sqrt(max(1.0 - sunX * sunX - muS * muS, 0.0)), muS);
  const float dTheta = kAtmospherePi / float(kSphereTheta), dPhi = 2.0 * kAtmospherePi / float(kSpherePhi);
  float altitude = r - atmBottom();
  vec3 density = vec3(0.0);
  vec3 rayleigh[NU], mie[NU];
  for (int l = 0; l < kSphereTheta; ++l) {
    float theta = (float(l) + 0.5) * dTheta;
    float cosTheta = cos(theta), sinTheta = sin(theta);
    bool hitsGround = atmRayHitsGround(r, cosTheta);
    float dGround = hitsGround ? atmDistanceToBottom(r, cosTheta) : 0.0;
    vec3 groundTransmittance = hitsGround ? atmTransmittance(r, cosTheta, dGround, true) : vec3(0.0);
    previousOrderSlices(r, cosTheta, muS, hitsGround, rayleigh, mie);
    for (int m = 0; m < kSpherePhi; ++m) {
      float phi = (float(m) + 0.5) * dPhi;
      vec3 omegaI = vec3(cos(phi) * sinTheta, sin(phi) * sinTheta, cosTheta);
      float solidAngle = dTheta * dPhi * sinTheta;
      vec3 incident = previousOrderAt(dot(omegaS, omegaI), rayleigh, mie);
      vec3 groundNormal = normalize(vec3(0.0, 0.0, r) + omegaI * dGround);
      incident += groundTransmittance * (atmosphere.misc.y / kAtmospherePi) * atmIrradiance(atmBottom(), dot(groundNormal, omegaS));
      float nu2 = dot(omega, omegaI);
      vec3 scatter = atmosphere.rayleigh.rgb * atmRayleighDensity(altitude) * atmRayleighPhase(nu2) +
                     atmosphere.mieScattering.rgb * atmMieDensity(altitude) * atmMiePhase(nu2);
      density += incident * scatter * solidAngle;
    }
  }
  return density;
}

vec3 computeIndirectIrradiance(float r, float muS) {
  vec3 omegaS = vec3(sqrt(max(1.0 - muS * muS, 0.0)), 0.0, muS);
  const float dTheta = 0.5 * kAtmospherePi / float(kSphereTheta), dPhi = 2.0 * kAtmospherePi / float(kSpherePhi);
  vec3 result = vec3(0.0);
  vec3 rayleigh[NU], mie[NU];
  for (int l = 0; l < kSphereTheta; ++l) {
    float theta = (float(l) + 0.5) * dTheta;
    previousOrderSlices(r, cos(theta), muS, false, rayleigh, mie);
    for (int m = 0; m < kSpherePhi; ++m) {
      float phi = (float(m) + 0.5) * dPhi;
      vec3 omegaI = vec3(cos(phi) * sin(theta), sin(phi) * sin(theta), cos(theta));
      result += previousOrderAt(dot(omegaI, omegaS), rayleigh, mie) * omegaI.z * dTheta * dPhi * sin(theta);
    }
  }
  return result;
}

vec3 computeMultipleScattering(vec4 p, bool hitsGround) {
  float r = p.x, mu = p.y, muS = p.z, nu = p.w;
  float length = atmDistanceToBoundary(r, mu, hitsGround);
  deltaBase = kDeltaDensity;
  vec3 sum = vec3(0.0);
  for (int i = 0; i <= kScatteringSteps; ++i) {
    vec2 step = raySample(i, kScatteringSteps, length, hitsGround);
    float d = step.x;
    float rd = atmClampRadius(sqrt(d * d + 2.0 * r * mu * d + r * r));
    float mud = atmClampCos((r * mu + d) / rd);
    float muSd = atmClampCos((r * muS + d * nu) / rd);
    vec3 j = atmScattering(rd, mud, muSd, nu, hitsGround).rgb;
    sum += j * atmTransmittance(r, mu, d, hitsGround) * step.y;
  }
  return sum;
}

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (kStep == GLOBE_ATMOSPHERE_TRANSMITTANCE) {
    if (index >= uint(GLOBE_TRANSMITTANCE_W * GLOBE_TRANSMITTANCE_H)) return;
    vec2 uv = (vec2(index % uint(GLOBE_TRANSMITTANCE_W), index / uint(GLOBE_TRANSMITTANCE_W)) + 0.5) /
              vec2(GLOBE_TRANSMITTANCE_W, GLOBE_TRANSMITTANCE_H);
    vec2 rMu = atmTransmittanceRMu(uv);
    transmittance[index] = vec4(computeTransmittance(rMu.x, rMu.y), 1.0);
  } else if (kStep == GLOBE_ATMOSPHERE_DIRECT_IRRADIANCE || kStep == GLOBE_ATMOSPHERE_INDIRECT_IRRADIANCE) {
    if (index >= uint(GLOBE_IRRADIANCE_W * GLOBE_IRRADIANCE_H)) return;
    vec2 uv = (vec2(index % uint(GLOBE_IRRADIANCE_W), index / uint(GLOBE_IRRADIANCE_W)) + 0.5) /
              vec2(GLOBE_IRRADIANCE_W, GLOBE_IRRADIANCE_H);
    vec2 rMuS = atmIrradianceRMuS(uv);
    if (kStep == GLOBE_ATMOSPHERE_DIRECT_IRRADIANCE) {
      // The sun's disc partly below the horizon: the average cosine over the visible part.
      float alpha = atmosphere.sun.w, muS = rMuS.y;
      float cosine = muS < -alpha ? 0.0 : (muS > alpha ? muS : (muS + alpha) * (muS + alpha) / (4.0 * alpha));
      deltaIrradiance[index] = vec4(atmosphere.sun.rgb * atmTransmittanceToTop(rMuS.x, muS) * cosine, 1.0);
      irradiance[index] = vec4(0.0, 0.0, 0.0, 1.0);
    } else {
      vec3 e = computeIndirectIrradiance(rMuS.x, rMuS.y);
      deltaIrradiance[index] = vec4(e, 1.0);
      irradiance[index] += vec4(e, 0.0);
    }
  } else {
    if (index >= uint(GLOBE_SCATTERING_TEXELS)) return;
    bool hitsGround;
    vec4 p = scatteringTexelParameters(index, hitsGround);
    if (kStep == GLOBE_ATMOSPHERE_SINGLE_SCATTERING) {
      vec3 rayleigh, mie;
      computeSingleScattering(p, hitsGround, rayleigh, mie);
      deltas[kDeltaRayleigh + index] = vec4(rayleigh, 0.0);
      deltas[kDeltaMie + index] = vec4(mie, 0.0);
      scattering[index] = vec4(rayleigh, mie.r);
    } else if (kStep == GLOBE_ATMOSPHERE_SCATTERING_DENSITY) {
      deltas[kDeltaDensity + index] = vec4(computeScatteringDensity(p), 0.0);
    } else {
      vec3 multiple = computeMultipleScattering(p, hitsGround);
      deltas[kDeltaRayleigh + index] = vec4(multiple, 0.0);
      scattering[index] += vec4(multiple / atmRayleighPhase(p.w), 0.0);
    }
  }
}
