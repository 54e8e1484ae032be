#pragma once
// A shaded, ramp-coloured preview of an equirectangular elevation map (`globe planet export --png`).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "shaders/include/colour_ramp.h"

namespace globe {

// Linear RGB per pixel (row-major, row 0 north) of the width x height map `elevation_m` (metres) of
// a planet of radius_m: the colour ramp at each pixel's elevation and true slope, times a hillshade
// lit from the north-west. The hillshade's relief is exaggerated by max(1, pixel size / 2 km) so
// that it stays visible at coarse widths; the ramp's rock and snow use the true slope.
std::vector<glm::vec3> shadeEquirect(std::span<const float> elevation_m, std::uint32_t width, std::uint32_t height,
                                     double radius_m, const gpu::ColourRampParams& ramp);

}  // namespace globe
