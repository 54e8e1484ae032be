#pragma once
// Procedural detail below a source's resolution (docs/elevation-data.md, "Amplification"): fBm of
// the engine's gradient noise (planet/core/gradient_noise.h) whose first octave has the
// source's pixel size as wavelength and whose amplitude is kAmplificationGain times the source's
// local relief per pixel. Every octave is zero-mean over its own wavelength, so averaged over a
// source pixel the detail vanishes and the source's heights are kept; where the source is flat
// (relief 0) nothing is added, so valleys and lakes stay flat.
#include <glm/vec3.hpp>

#include <cstdint>

namespace globe {

// First octave's amplitude per metre of local relief per pixel.
inline constexpr double kAmplificationGain = 0.25;
// Octaves stop once the wavelength is below this (metres).
inline constexpr double kAmplificationFinestWavelength_m = 1.0;
inline constexpr int kAmplificationMaxOctaves = 10;

// Octaves from `pixel_m` down to kAmplificationFinestWavelength_m (at least 1).
int amplificationOctaves(double pixel_m);

// The detail (metres) at `unitDirection` on a sphere of `radius_m` where the local relief is
// `relief_m` per pixel.
double amplificationDetail_m(const glm::dvec3& unitDirection, double radius_m, double pixel_m, int octaves,
                             std::uint32_t seed, double relief_m);

// Bound of |amplificationDetail_m| per metre of relief.
double amplificationBoundPerRelief(int octaves);

}  // namespace globe
