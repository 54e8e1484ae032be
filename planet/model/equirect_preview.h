#pragma once
// A shaded, ramp-coloured preview of an equirectangular elevation map (`globe planet export --png`).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "planet/model/planet_description.h"

namespace globe {

// Linear RGB per pixel (row-major, row 0 north) of the width x height map `elevation_m` (metres) of
// a planet of radius_m: the colour ramp at each pixel's elevation and true slope, times a hillshade
// lit from the north-west. The hillshade's relief is exaggerated by max(1, pixel size / 2 km) so
// that it stays visible at coarse widths; the ramp's rock and snow use the true slope. On a planet with
// water, ground below sea level is the sea: its colour tinted by depth, flat (as the renderer draws it).
// `albedo`, when not empty (one linear colour per pixel: the land cover map, landCoverEquirectRows in
// planet/model/surface_sample.h), colours the ground instead of the ramp.
std::vector<glm::vec3> shadeEquirect(std::span<const float> elevation_m, std::uint32_t width, std::uint32_t height,
                                     const PlanetDescription& planet, std::span<const glm::vec3> albedo = {});

}  // namespace globe
