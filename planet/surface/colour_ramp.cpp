#include "planet/surface/colour_ramp.h"

#include "planet/core/finite_range.h"

#include <fmt/format.h>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>

namespace globe {

std::vector<ColourRampStop> defaultColourRampStops() {
  // Linear RGB (sRGB-looking values squared, roughly): deep ocean to bare peaks.
  return {
      {-6000.0, glm::vec3(0.005f, 0.015f, 0.060f)},  // abyssal plain
      {-200.0, glm::vec3(0.020f, 0.080f, 0.200f)},   // continental shelf
      {0.0, glm::vec3(0.450f, 0.400f, 0.280f)},      // beach
      {150.0, glm::vec3(0.080f, 0.180f, 0.040f)},    // lowland vegetation
      {1500.0, glm::vec3(0.200f, 0.180f, 0.080f)},   // dry highland
      {3500.0, glm::vec3(0.300f, 0.270f, 0.240f)},   // bare rock
      {5000.0, glm::vec3(0.550f, 0.550f, 0.560f)},   // high peaks
  };
}

namespace {

void checkColour(const glm::vec3& c, const std::string& field, std::vector<Error>& errors) {
  for (int i = 0; i < 3; ++i) {
    if (!inRange(static_cast<double>(c[i]), 0.0, 1.0)) {
      errors.push_back(Error::inField(field, "each component must be within [0, 1] (linear RGB)"));
      return;
    }
  }
}

float hardEdgeInverse(double range) { return range > 0.0 ? static_cast<float>(1.0 / range) : 1e30f; }

double cosDeg(double degrees) { return std::cos(degrees * std::numbers::pi / 180.0); }

}  // namespace

void appendColourRampErrors(const ColourRamp& ramp, std::vector<Error>& errors) {
  if (ramp.stops.size() < 2 || ramp.stops.size() > static_cast<std::size_t>(kMaxColourStops)) {
    errors.push_back(Error::inField("colour_ramp", fmt::format("need 2 to {} stops", kMaxColourStops)));
  }
  for (std::size_t i = 0; i < ramp.stops.size(); ++i) {
    const std::string p = fmt::format("colour_ramp[{}].", i);
    const ColourRampStop& s = ramp.stops[i];
    if (!inRange(s.elevation_m, -1e7, 1e7)) {
      errors.push_back(Error::inField(p + "elevation_m", "must be within [-1e7, 1e7] m"));
    } else if (i > 0 && !(s.elevation_m > ramp.stops[i - 1].elevation_m)) {
      errors.push_back(Error::inField(
          p + "elevation_m",
          fmt::format("must be greater than the previous stop's ({:g} m)", ramp.stops[i - 1].elevation_m)));
    }
    checkColour(s.colour, p + "colour", errors);
  }
  if (!inRange(ramp.rock_slope_deg, 0.0, 90.0)) {
    errors.push_back(Error::inField("rock.slope_deg", "must be within [0, 90] degrees"));
  }
  if (!inRange(ramp.rock_blend_deg, 0.0, 90.0)) {
    errors.push_back(Error::inField("rock.blend_deg", "must be within [0, 90] degrees"));
  }
  checkColour(ramp.rock_colour, "rock.colour", errors);
  if (!inRange(ramp.snow_elevation_m, -1e7, 1e7)) {
    errors.push_back(Error::inField("snow.elevation_m", "must be within [-1e7, 1e7] m"));
  }
  if (!inRange(ramp.snow_blend_m, 0.0, 1e7)) {
    errors.push_back(Error::inField("snow.blend_m", "must be within [0, 1e7] m"));
  }
  if (!inRange(ramp.snow_max_slope_deg, 0.0, 90.0)) {
    errors.push_back(Error::inField("snow.max_slope_deg", "must be within [0, 90] degrees"));
  }
  checkColour(ramp.snow_colour, "snow.colour", errors);
}

void appendWaterErrors(const Water& water, std::vector<Error>& errors) {
  if (!water.enabled) return;
  checkColour(water.shallow_colour, "water.shallow_colour", errors);
  checkColour(water.deep_colour, "water.deep_colour", errors);
  if (!(inRange(water.depth_scale_m, 0.0, 1e5) && water.depth_scale_m > 0.0))
    errors.push_back(Error::inField("water.depth_scale_m", "must be within (0, 1e5] m"));
}

glm::vec3 seaColour(const Water& water, double depth_m) {
  const float murk = static_cast<float>(1.0 - std::exp(-depth_m / water.depth_scale_m));
  return glm::mix(water.shallow_colour, water.deep_colour, murk);
}

gpu::ColourRampParams packColourRamp(const ColourRamp& ramp) {
  gpu::ColourRampParams p{};
  const std::size_t n = std::min(ramp.stops.size(), static_cast<std::size_t>(kMaxColourStops));
  assert(n >= 2);
  p.stop_count = static_cast<gpu::uint>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ColourRampStop& s = ramp.stops[i];
    p.stops[i] = gpu::ColourStop{static_cast<float>(s.elevation_m), s.colour.x, s.colour.y, s.colour.z};
  }
  const double start_deg = std::max(0.0, ramp.rock_slope_deg - 0.5 * ramp.rock_blend_deg);
  const double full_deg = std::min(90.0, ramp.rock_slope_deg + 0.5 * ramp.rock_blend_deg);
  const double cos_start = cosDeg(start_deg);
  p.rock_cos_start = static_cast<float>(cos_start);
  p.rock_inv_range = hardEdgeInverse(cos_start - cosDeg(full_deg));
  p.rock = gpu::ColourStop{0.0f, ramp.rock_colour.x, ramp.rock_colour.y, ramp.rock_colour.z};
  p.snow_enabled = ramp.snow ? 1U : 0U;
  p.snow_elevation_m = static_cast<float>(ramp.snow_elevation_m);
  p.snow_inv_blend = hardEdgeInverse(ramp.snow_blend_m);
  p.snow_cos_min = static_cast<float>(cosDeg(ramp.snow_max_slope_deg));
  p.snow = gpu::ColourStop{0.0f, ramp.snow_colour.x, ramp.snow_colour.y, ramp.snow_colour.z};
  return p;
}

namespace {

glm::vec3 mix(const glm::vec3& a, const glm::vec3& b, float t) { return a + (b - a) * t; }
glm::vec3 colourOf(const gpu::ColourStop& s) { return glm::vec3(s.r, s.g, s.b); }

}  // namespace

glm::vec3 rampColour(const gpu::ColourRampParams& ramp, double elevation_m, double cos_slope) {
  const auto h = static_cast<float>(elevation_m);
  const auto c = static_cast<float>(cos_slope);
  const gpu::uint n = ramp.stop_count;
  glm::vec3 base = colourOf(ramp.stops[0]);
  if (h >= ramp.stops[n - 1].elevation_m) {
    base = colourOf(ramp.stops[n - 1]);
  } else {
    for (gpu::uint i = 1; i < n; ++i) {
      if (h < ramp.stops[i].elevation_m) {
        const gpu::ColourStop& a = ramp.stops[i - 1];
        const gpu::ColourStop& b = ramp.stops[i];
        const float t = std::clamp((h - a.elevation_m) / (b.elevation_m - a.elevation_m), 0.0f, 1.0f);
        base = mix(colourOf(a), colourOf(b), t);
        break;
      }
    }
  }
  const float r = std::clamp((ramp.rock_cos_start - c) * ramp.rock_inv_range, 0.0f, 1.0f);
  glm::vec3 colour = mix(base, colourOf(ramp.rock), r * r * (3.0f - 2.0f * r));
  if (ramp.snow_enabled != 0U && c >= ramp.snow_cos_min) {
    const float s = std::clamp((h - ramp.snow_elevation_m) * ramp.snow_inv_blend, 0.0f, 1.0f);
    colour = mix(colour, colourOf(ramp.snow), s);
  }
  return colour;
}

}  // namespace globe
