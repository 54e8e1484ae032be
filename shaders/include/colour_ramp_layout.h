// Surface colour of a planet by elevation and slope, shared by C++ (planet/surface/colour_ramp.h) and GLSL.
// This file compiles as both: C++ sees namespace globe::gpu and static_asserts, GLSL sees plain
// structs. Layout: identical under std430 and std140 (32-bit scalars only, every struct a multiple
// of 16 bytes, ColourStop arrays have a 16-byte stride in both). C++ fills it with
// globe::packColourRamp(ColourRamp) and uploads the bytes as they are; globe::rampColour
// (planet/surface/colour_ramp.cpp) is the reference evaluation a shader mirrors:
//   base  = linear interpolation of the stops at elevation h (clamped to the end stops)
//   rock  = smoothstep(clamp((rock_cos_start - cos_slope) * rock_inv_range, 0, 1))
//   snow  = snow_enabled && cos_slope >= snow_cos_min ? clamp((h - snow_elevation_m) * snow_inv_blend, 0, 1) : 0
//   colour = mix(mix(base, rock_colour, rock), snow_colour, snow)
// where cos_slope = dot(surface normal, radial up) and h is the elevation above radius_m in metres
// (the same value as the elevation function; sea level is not subtracted).
#ifndef GLOBE_COLOUR_RAMP_H
#define GLOBE_COLOUR_RAMP_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace globe::gpu {
using uint = std::uint32_t;
#endif

// Most stops a colour ramp can have (the GPU struct is fixed-size).
#define GLOBE_MAX_COLOUR_STOPS 16

// One stop or one colour (16 bytes). Floats are enough: colours are 8-bit on screen and an
// elevation step of 2^-24 relative (6 cm at 1e6 m) is invisible in a colour.
struct ColourStop {
  float elevation_m;  //  0: elevation of the stop, metres (unused for rock/snow colours)
  float r;            //  4: linear colour, 0..1
  float g;            //  8
  float b;            // 12
};

// The whole ramp (64 + 16 * 16 = 320 bytes).
struct ColourRampParams {
  uint stop_count;         //  0: stops in use, 2 .. GLOBE_MAX_COLOUR_STOPS, elevations increasing
  float rock_cos_start;    //  4: cos(slope) below which rock starts to show
  float rock_inv_range;    //  8: 1 / (rock_cos_start - cos(slope where rock is full)), 1e30 for a hard edge
  float snow_elevation_m;  // 12: elevation where snow starts, metres
  float snow_inv_blend;    // 16: 1 / (elevation range over which snow becomes full), per metre
  float snow_cos_min;      // 20: no snow where cos(slope) < this (too steep to hold snow)
  uint snow_enabled;       // 24: 0 or 1
  uint pad0;               // 28
  ColourStop rock;         // 32: colour of steep slopes (elevation_m unused)
  ColourStop snow;         // 48: colour of snow (elevation_m unused)
  ColourStop stops[GLOBE_MAX_COLOUR_STOPS];  // 64
};

#ifdef __cplusplus
static_assert(sizeof(ColourStop) == 16);
static_assert(offsetof(ColourRampParams, rock) == 32);
static_assert(offsetof(ColourRampParams, stops) == 64);
static_assert(sizeof(ColourRampParams) == 320);
}  // namespace globe::gpu
#endif

#endif  // GLOBE_COLOUR_RAMP_H
