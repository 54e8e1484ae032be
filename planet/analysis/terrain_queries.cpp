#include "planet/analysis/terrain_queries.h"

#include "planet/streaming/payload_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace globe {

TerrainQueries::TerrainQueries(const ElevationModel& model) : model_(model), rays_(model) {}

double TerrainQueries::exactHeight_m(const glm::dvec3& unitDirection) const {
  return model_.elevation_m(unitDirection);
}

double TerrainQueries::drawnHeight_m(const glm::dvec3& unitDirection, int level, uint32_t cells) const {
  return drawnSurfaceRadius(model_, unitDirection, level, cells) - model_.radius_m();
}

double TerrainQueries::cameraFloorRadius(const glm::dvec3& unitDirection, int level, uint32_t cells) const {
  return std::max(model_.radius_m() + model_.visibleElevation_m(unitDirection),
                  drawnSurfaceRadius(model_, unitDirection, level, cells));
}

std::optional<double> TerrainQueries::rayExact(const glm::dvec3& origin_m, const glm::dvec3& direction,
                                               double maxDistance_m) const {
  SurfaceRayOptions options;
  options.tolerance_m = 1e-4;
  options.pixelAngle_rad = 1e-5;  // minimum step 5e-7 of the distance: finer than any camera move
  options.maxDistance_m = maxDistance_m;
  const SurfaceRayHit hit = rays_.cast(origin_m, direction, options);
  if (hit.kind != SurfaceRayHit::Kind::kHit || hit.distance_m > maxDistance_m) return std::nullopt;
  return hit.distance_m;
}

glm::dvec3 TerrainQueries::guardedMove(const glm::dvec3& from_m, const glm::dvec3& to_m, double clearance_m, int level,
                                       uint32_t cells) const {
  glm::dvec3 to = to_m;
  const glm::dvec3 travel = to_m - from_m;
  const double length = glm::length(travel);
  if (length > 0.0) {
    const glm::dvec3 direction = travel / length;
    if (auto hit = rayExact(from_m, direction, length + clearance_m))
      to = from_m + direction * std::max(0.0, std::min(length, *hit - clearance_m));
  }
  const Ellipsoid& shape = model_.shape();
  if (!shape.isSphere()) {  // the floor along the normal below, through GeographicLib
    const GeodeticPoint g = shape.geodeticFromGeocentric(to);
    const double floor = cameraFloorRadius(Ellipsoid::normalAt(g), level, cells) + clearance_m;
    const double height = g.height_m + shape.equatorialRadius_m();  // as a reference radius
    return height < floor ? shape.pointAbove(g.latitude_deg, g.longitude_deg, floor, 0.0) : to;
  }
  const double r = glm::length(to);
  const glm::dvec3 up = to / r;
  const double floor = cameraFloorRadius(up, level, cells) + clearance_m;
  return r < floor ? up * floor : to;
}

}  // namespace globe
