// The phase functions of the atmosphere's two media (per steradian, nu the cosine between the ray
// and the sun): Rayleigh, and Cornette-Shanks for Mie with asymmetry g. Shared by the tables' model
// (atmosphere_model.glsl) and the analytic haze (terrain_haze.glsl).
#ifndef GLOBE_ATMOSPHERE_PHASE_GLSL
#define GLOBE_ATMOSPHERE_PHASE_GLSL

const float kAtmospherePi = 3.14159265358979;

float atmRayleighPhase(float nu) { return 3.0 / (16.0 * kAtmospherePi) * (1.0 + nu * nu); }
float atmCornetteShanksPhase(float nu, float g) {
  float k = 3.0 / (8.0 * kAtmospherePi) * (1.0 - g * g) / (2.0 + g * g);
  return k * (1.0 + nu * nu) / pow(max(1.0 + g * g - 2.0 * g * nu, 1e-6), 1.5);
}

#endif  // GLOBE_ATMOSPHERE_PHASE_GLSL
