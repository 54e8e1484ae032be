#include "planet/model/equirect_preview.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "planet/surface/colour_ramp.h"

namespace globe {

std::vector<glm::vec3> shadeEquirect(std::span<const float> elevation_m, std::uint32_t width, std::uint32_t height,
                                     const PlanetDescription& planet, std::span<const glm::vec3> albedo) {
  assert(elevation_m.size() == static_cast<std::size_t>(width) * height);
  assert(albedo.empty() || albedo.size() == elevation_m.size());
  const double radius_m = planet.radius_m;
  const gpu::ColourRampParams ramp = packColourRamp(planet.colour_ramp);
  const Water& water = planet.water;
  std::vector<glm::vec3> rgb(elevation_m.size());
  const double dy_m = std::numbers::pi * radius_m / static_cast<double>(height);  // north-south pixel size
  const double dx_equator_m = 2.0 * std::numbers::pi * radius_m / static_cast<double>(width);
  const double exaggeration = std::max(1.0, dx_equator_m / 2000.0);
  const glm::dvec3 sun = glm::normalize(glm::dvec3(-1.0, 1.0, 1.2));  // east, north, up
  auto at = [&](std::int64_t x, std::int64_t y) {
    x = (x + width) % width;  // longitude wraps
    y = std::clamp<std::int64_t>(y, 0, height - 1);
    return static_cast<double>(elevation_m[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)]);
  };
  for (std::uint32_t y = 0; y < height; ++y) {
    const double lat = std::numbers::pi * (0.5 - (y + 0.5) / height);
    const double dx_m = std::max(dx_equator_m * std::cos(lat), 1e-9 * radius_m);
    for (std::uint32_t x = 0; x < width; ++x) {
      const auto xi = static_cast<std::int64_t>(x);
      const auto yi = static_cast<std::int64_t>(y);
      const double depth_m = planet.sea_level_m - at(xi, yi);
      if (water.enabled && depth_m > 0.0) {
        rgb[static_cast<std::size_t>(y) * width + x] = seaColour(water, depth_m);
        continue;
      }
      const double gx = (at(xi + 1, yi) - at(xi - 1, yi)) / (2.0 * dx_m);  // rise per metre eastwards
      const double gy = (at(xi, yi - 1) - at(xi, yi + 1)) / (2.0 * dy_m);  // rise per metre northwards
      const double cos_slope = 1.0 / std::sqrt(1.0 + gx * gx + gy * gy);
      const glm::dvec3 n = glm::normalize(glm::dvec3(-gx * exaggeration, -gy * exaggeration, 1.0));
      const double light = 0.35 + 0.65 * std::max(0.0, glm::dot(n, sun)) / sun.z;
      const glm::vec3 c =
          albedo.empty() ? rampColour(ramp, at(xi, yi), cos_slope) : albedo[static_cast<std::size_t>(y) * width + x];
      rgb[static_cast<std::size_t>(y) * width + x] = c * static_cast<float>(std::min(light, 1.5));
    }
  }
  return rgb;
}

}  // namespace globe
