// The atmosphere's parameters as the shaders see them, and the sizes and layouts of its lookup
// tables (engine/atmosphere/atmosphere_luts.*, shaders/atmosphere_precompute.comp, atmosphere.glsl).
// Shared by C++ (namespace globe::gpu) and GLSL like terrain_layout.h. Lengths in metres.
//
// Tables (storage buffers of vec4, row-major, x fastest), parameterised as in [Bruneton & Neyret
// 2008] and its 2017 reference (docs/rendering.md, "Atmosphere"):
//   transmittance   (mu, r)               TRANSMITTANCE_W x TRANSMITTANCE_H, rgb
//   irradiance      (mu_s, r)             IRRADIANCE_W x IRRADIANCE_H, rgb (sky light on the ground, no sun)
//   scattering      (nu, mu_s, mu, r)     index ((r * MU + mu) * MU_S + mu_s) * NU + nu: rgb = Rayleigh and
//                                         multiple scattering without the Rayleigh phase, a = single Mie's red
#ifndef GLOBE_ATMOSPHERE_LAYOUT_H
#define GLOBE_ATMOSPHERE_LAYOUT_H

#define GLOBE_TRANSMITTANCE_W 256
#define GLOBE_TRANSMITTANCE_H 64
#define GLOBE_IRRADIANCE_W 64
#define GLOBE_IRRADIANCE_H 16
#define GLOBE_SCATTERING_R 32
#define GLOBE_SCATTERING_MU 64
#define GLOBE_SCATTERING_MU_S 16
#define GLOBE_SCATTERING_NU 8
#define GLOBE_SCATTERING_TEXELS (GLOBE_SCATTERING_R * GLOBE_SCATTERING_MU * GLOBE_SCATTERING_MU_S * GLOBE_SCATTERING_NU)

// The per-frame aerial perspective table (atmosphere_view.glsl, atmosphere_view.comp): in-scattered
// light and transmittance from the camera to a point, over the screen's directions (x, y of NDC
// within +-GLOBE_VIEW_EXTENT) x the distance along the ray (logarithmic, over the stretch where
// terrain can be). One uvec4 of half floats per texel, x fastest; two more texels after the
// table hold the sky's zenith and horizon colours (for the water's reflection).
#define GLOBE_VIEW_X 16
#define GLOBE_VIEW_Y 32
#define GLOBE_VIEW_D 16
#define GLOBE_VIEW_EXTENT 1.25
#define GLOBE_VIEW_TEXELS (GLOBE_VIEW_X * GLOBE_VIEW_Y * GLOBE_VIEW_D)

// Precomputation steps (specialization constant 0 of atmosphere_precompute.comp).
#define GLOBE_ATMOSPHERE_TRANSMITTANCE 0u
#define GLOBE_ATMOSPHERE_DIRECT_IRRADIANCE 1u
#define GLOBE_ATMOSPHERE_SINGLE_SCATTERING 2u
#define GLOBE_ATMOSPHERE_SCATTERING_DENSITY 3u
#define GLOBE_ATMOSPHERE_INDIRECT_IRRADIANCE 4u
#define GLOBE_ATMOSPHERE_MULTIPLE_SCATTERING 5u

#ifdef __cplusplus
namespace globe::gpu {
struct AtmosphereVec4 {
  float x, y, z, w;
};
#define GLOBE_VEC4 AtmosphereVec4
#else
#define GLOBE_VEC4 vec4
#endif

// std140 = std430 (vec4 only), 112 bytes.
struct AtmosphereGpu {
  GLOBE_VEC4 radii;          //  0: x = bottom radius, y = top radius, z = mu_s min (the tables' lowest sun), w = 0
  GLOBE_VEC4 rayleigh;       // 16: rgb = scattering per metre, w = scale height
  GLOBE_VEC4 mieScattering;  // 32: rgb = scattering per metre, w = scale height
  GLOBE_VEC4 mieExtinction;  // 48: rgb = extinction per metre, w = g
  GLOBE_VEC4 ozone;          // 64: rgb = absorption per metre at the peak, w = peak altitude
  GLOBE_VEC4 sun;            // 80: rgb = irradiance at the top, w = angular radius (radians)
  GLOBE_VEC4 misc;           // 96: x = ozone half width, y = ground albedo, z = exposure, w = cos(sun radius)
};

// The camera of one frame, for the aerial perspective table (std140 = std430, 96 bytes).
struct AtmosphereViewGpu {
  GLOBE_VEC4 camera;   //  0: xyz = camera minus planet centre (m), w = 0
  GLOBE_VEC4 sun;      // 16: xyz = unit, towards the sun
  GLOBE_VEC4 right;    // 32: xyz = unit right, w = tan(horizontal fov / 2)
  GLOBE_VEC4 up;       // 48: xyz = unit up, w = tan(vertical fov / 2)
  GLOBE_VEC4 forward;  // 64: xyz = unit view direction
  GLOBE_VEC4 terrain;  // 80: x = radius of the lowest terrain, y = of the highest (m)
};

#ifdef __cplusplus
static_assert(sizeof(AtmosphereGpu) == 112);
static_assert(sizeof(AtmosphereViewGpu) == 96);
}  // namespace globe::gpu
#endif
#undef GLOBE_VEC4

#endif  // GLOBE_ATMOSPHERE_LAYOUT_H
