#pragma once
// What the land cover rules read at one point of a planet, from the CPU elevation reference: the
// drawn elevation, the first layer's value and the ground's slope by finite differences. Shared by
// `globe planet stats` and `globe planet export` (engine/cli), and their sphere-wide loops.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "planet/core/parallel_for.h"
#include "planet/model/elevation_model.h"
#include "planet/surface/land_cover.h"

namespace globe {

// The spacing of the slope's finite differences in stats and export (metres).
inline constexpr double kLandCoverSlopeSpacing_m = 30.0;

// Cosine of the angle between the ground's normal and the vertical (the unit direction, the geodetic
// normal) at a unit direction: central differences of the ground's surface points spacing_m apart
// (metres along the reference surface) along two tangent directions, in double.
double groundCosSlope(const ElevationModel& model, const glm::dvec3& unit_direction, double spacing_m);

// The land cover's inputs at a unit direction whose ground elevation is ground_m
// (model.elevation_m(unit_direction)): the drawn elevation (max(ground, sea level) on a planet with
// [water], as the renderer draws it), model.firstLayer_m and groundCosSlope.
LandCoverSite landCoverSiteAt(const ElevationModel& model, const glm::dvec3& unit_direction, double spacing_m,
                              double ground_m);
// The same, evaluating the ground elevation itself.
LandCoverSite landCoverSiteAt(const ElevationModel& model, const glm::dvec3& unit_direction, double spacing_m);

// Area shares of a planet's land cover over `samples` Fibonacci-sphere directions (the stats'
// directions): the drawn sea, then each class's mean mask over the land, both as fractions of the
// whole planet (they sum to 1). Deterministic: integer sums, independent of `threads`.
struct LandCoverShares {
  std::uint64_t samples = 0;
  double sea_fraction = 0.0;           // ground below sea level on a planet with [water]; 0 otherwise
  std::vector<double> class_fraction;  // one per class
};
// The model must have land cover (landCover().class_count > 0).
LandCoverShares computeLandCoverShares(const ElevationModel& model, std::uint64_t samples, unsigned threads,
                                       const ProgressFn& progress = {});

// The land cover map of rows [first_row, first_row + out.size() / width) of a width x height
// equirectangular map (pixel centres as sampleEquirectRows): each land pixel the albedo of its masks
// (landCoverAlbedo), each pixel under drawn water seaColour by its depth. Linear RGB, row-major.
void landCoverEquirectRows(const ElevationModel& model, std::uint32_t width, std::uint32_t height,
                           std::uint32_t first_row, std::span<glm::vec3> out, unsigned threads,
                           const ProgressFn& progress = {});

}  // namespace globe
