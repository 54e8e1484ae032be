#include "planet/tiling/horizon_occlusion.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace globe {

std::optional<glm::dvec3> horizonOcclusionPoint(std::span<const glm::dvec3> positions_m, const glm::dvec3& radii_m,
                                                const glm::dvec3& direction) {
  double t = 1.0;
  for (const glm::dvec3& p_m : positions_m) {
    const glm::dvec3 p = p_m / radii_m;
    const double m = std::max(1.0, glm::length(p));
    const glm::dvec3 unit = glm::normalize(p);
    const double cos_alpha = glm::dot(direction, unit);
    const double sin_alpha = glm::length(glm::cross(direction, unit));
    const double cos_beta = 1.0 / m;
    const double sin_beta = std::sqrt(m * m - 1.0) / m;
    const double cos_sum = cos_alpha * cos_beta - sin_alpha * sin_beta;  // cos(alpha + beta)
    if (cos_sum <= 1e-9) return std::nullopt;
    t = std::max(t, 1.0 / cos_sum);
  }
  return direction * t;
}

bool insideHorizonCone(const glm::dvec3& scaled_point, const glm::dvec3& scaled_horizon_point, double slack) {
  const double t = glm::length(scaled_horizon_point);
  if (t <= 1.0) return false;
  const double half_angle = std::asin(1.0 / t);
  glm::dvec3 p = scaled_point;
  if (glm::length(p) < 1.0) p = glm::normalize(p);  // under the surface: as on it
  const glm::dvec3 to_point = p - scaled_horizon_point;
  const double len = glm::length(to_point);
  if (len == 0.0) return true;
  const double cos_angle = std::clamp(glm::dot(to_point / len, -scaled_horizon_point / t), -1.0, 1.0);
  return std::acos(cos_angle) <= half_angle + slack;
}

}  // namespace globe
