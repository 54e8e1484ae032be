#include "planet/surface/land_cover.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "planet/core/finite_range.h"
#include "planet/core/gradient_noise.h"

namespace globe {

namespace {

void checkNumber(double v, double lo, double hi, const std::string& field, std::vector<Error>& errors) {
  if (!inRange(v, lo, hi)) errors.push_back(Error::inField(field, fmt::format("must be within [{:g}, {:g}]", lo, hi)));
}

void checkPositive(double v, double hi, const std::string& field, std::vector<Error>& errors) {
  if (!(std::isfinite(v) && v > 0.0 && v <= hi))
    errors.push_back(Error::inField(field, fmt::format("must be within (0, {:g}]", hi)));
}

// A class range: both ends within [lo, hi] (or unbounded) and min < max.
void checkRange(double min, double max, double lo, double hi, const std::string& field, std::vector<Error>& errors) {
  auto ok = [&](double v) { return std::abs(v) == kUnboundedRange || inRange(v, lo, hi); };
  if (!ok(min) || !ok(max)) {
    errors.push_back(Error::inField(field, fmt::format("each end must be within [{:g}, {:g}]", lo, hi)));
  } else if (!(min < max)) {
    errors.push_back(Error::inField(field, "the first value must be below the second"));
  }
}

bool validName(const std::string& name) {
  return !name.empty() && name.size() <= 32 && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

void appendClimateErrors(const Climate& c, std::vector<Error>& errors) {
  checkNumber(c.equator_temperature_c, -300.0, 1000.0, "climate.equator_temperature_c", errors);
  checkNumber(c.pole_temperature_c, -300.0, 1000.0, "climate.pole_temperature_c", errors);
  checkNumber(c.lapse_rate_c_per_km, 0.0, 100.0, "climate.lapse_rate_c_per_km", errors);
  checkNumber(c.temperature_noise_c, 0.0, 200.0, "climate.temperature_noise_c", errors);
  checkNumber(c.moisture_base, -10.0, 10.0, "climate.moisture_base", errors);
  checkNumber(c.moisture_noise, 0.0, 10.0, "climate.moisture_noise", errors);
  checkNumber(c.inland_drying_m, 1.0, 1e7, "climate.inland_drying_m", errors);
  checkPositive(c.noise_wavelength_m, 1e9, "climate.noise_wavelength_m", errors);
  checkPositive(c.temperature_blend_c, 1000.0, "climate.temperature_blend_c", errors);
  checkPositive(c.moisture_blend, 10.0, "climate.moisture_blend", errors);
  checkPositive(c.elevation_blend_m, 1e7, "climate.elevation_blend_m", errors);
  checkPositive(c.slope_blend_deg, 90.0, "climate.slope_blend_deg", errors);
}

// Weight of x within [lo, hi] with soft edges `blend` wide (shaders/include/land_cover.glsl).
float smoothEdge(float x, float edge, float blend) {
  float t = std::clamp((x - edge) / blend + 0.5f, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

float band(float x, float lo, float hi, float blend) {
  return smoothEdge(x, lo, blend) * (1.0f - smoothEdge(x, hi, blend));
}

// 3 octaves of gradient noise, lacunarity 2, gain 0.5, in float (= climateNoise in GLSL).
float climateNoise(glm::vec3 p, std::uint32_t seed) {
  float sum = 0.0f, amplitude = 1.0f;
  for (int o = 0; o < 3; ++o) {
    sum += amplitude * gradientNoise(p.x, p.y, p.z, seed);
    p *= 2.0f;
    amplitude *= 0.5f;
    seed += 0x9e3779b9U;
  }
  return sum;
}

}  // namespace

void appendLandCoverErrors(const LandCover& cover, std::vector<Error>& errors) {
  if (!cover.enabled()) return;
  appendClimateErrors(cover.climate, errors);
  if (cover.classes.size() > static_cast<std::size_t>(kMaxLandCoverClasses))
    errors.push_back(Error::inField("land_cover", fmt::format("at most {} classes", kMaxLandCoverClasses)));
  std::set<std::string> names;
  for (std::size_t i = 0; i < cover.classes.size(); ++i) {
    const LandCoverClass& c = cover.classes[i];
    const std::string p = fmt::format("land_cover[{}].", i);
    if (!validName(c.name)) {
      errors.push_back(Error::inField(p + "name", "must be 1 to 32 characters of a-z, 0-9, _ and -"));
    } else if (c.name == "sea") {
      // `globe planet stats` prints the area under the sea as "land_cover sea".
      errors.push_back(Error::inField(p + "name", "'sea' is reserved (the area under the water in planet stats)"));
    } else if (!names.insert(c.name).second) {
      errors.push_back(Error::inField(p + "name", "'" + c.name + "' is already the name of an earlier class"));
    }
    checkRange(c.temperature_min_c, c.temperature_max_c, -1000.0, 1000.0, p + "temperature_c", errors);
    checkRange(c.moisture_min, c.moisture_max, -10.0, 10.0, p + "moisture", errors);
    checkRange(c.elevation_min_m, c.elevation_max_m, -1e7, 1e7, p + "elevation_m", errors);
    checkRange(c.slope_min_deg, c.slope_max_deg, 0.0, 90.0, p + "slope_deg", errors);
    for (int k = 0; k < 3; ++k) {
      if (!inRange(c.colour[k], 0.0, 1.0)) {
        errors.push_back(Error::inField(p + "colour", "each component must be within [0, 1] (linear RGB)"));
        break;
      }
    }
    checkNumber(c.detail_contrast, 0.0, 1.0, p + "detail_contrast", errors);
  }
}

gpu::LandCoverParams packLandCover(const LandCover& cover, double radius_m, std::uint64_t planet_seed,
                                   double sea_level_m) {
  gpu::LandCoverParams p{};
  p.class_count = static_cast<gpu::uint>(cover.classes.size());
  const Climate& c = cover.climate;
  // A seed of its own, apart from the layers' (which hash the seed with the layer index).
  p.seed = static_cast<gpu::uint>((planet_seed ^ (planet_seed >> 32)) * 0x2545f491ULL) ^ 0x6c616e64U;
  p.noise_scale = static_cast<float>(radius_m / c.noise_wavelength_m);
  p.equator_temperature_c = static_cast<float>(c.equator_temperature_c);
  p.pole_temperature_c = static_cast<float>(c.pole_temperature_c);
  p.lapse_rate_c_per_m = static_cast<float>(c.lapse_rate_c_per_km / 1000.0);
  p.temperature_noise_c = static_cast<float>(c.temperature_noise_c);
  p.moisture_base = static_cast<float>(c.moisture_base);
  p.moisture_noise = static_cast<float>(c.moisture_noise);
  p.inland_drying_per_m = static_cast<float>(1.0 / c.inland_drying_m);
  p.sea_level_m = static_cast<float>(sea_level_m);
  p.temperature_blend_c = static_cast<float>(c.temperature_blend_c);
  p.moisture_blend = static_cast<float>(c.moisture_blend);
  p.elevation_blend_m = static_cast<float>(c.elevation_blend_m);
  p.slope_blend_deg = static_cast<float>(c.slope_blend_deg);
  for (std::size_t i = 0; i < cover.classes.size() && i < GLOBE_MAX_LAND_COVER_CLASSES; ++i) {
    const LandCoverClass& k = cover.classes[i];
    gpu::LandCoverClassParams& g = p.classes[i];
    g.temperature_min_c = static_cast<float>(k.temperature_min_c);
    g.temperature_max_c = static_cast<float>(k.temperature_max_c);
    g.moisture_min = static_cast<float>(k.moisture_min);
    g.moisture_max = static_cast<float>(k.moisture_max);
    g.elevation_min_m = static_cast<float>(k.elevation_min_m);
    g.elevation_max_m = static_cast<float>(k.elevation_max_m);
    g.slope_min_deg = static_cast<float>(k.slope_min_deg);
    g.slope_max_deg = static_cast<float>(k.slope_max_deg);
    g.r = k.colour.x;
    g.g = k.colour.y;
    g.b = k.colour.z;
  }
  return p;
}

ClimateSample climateAt(const gpu::LandCoverParams& p, const LandCoverSite& site) {
  const glm::vec3 d(site.unit_direction);
  const glm::vec3 q = d * p.noise_scale;
  const float nT = climateNoise(q, p.seed);
  const float nM = climateNoise(q, p.seed + 1U);
  const float above = static_cast<float>(site.elevation_m) - p.sea_level_m;
  const float inland = std::max(static_cast<float>(site.first_layer_m) - p.sea_level_m, 0.0f);
  const float lat2 = d.z * d.z;
  ClimateSample out;
  out.temperature_c = p.equator_temperature_c + (p.pole_temperature_c - p.equator_temperature_c) * lat2 +
                      p.temperature_noise_c * nT - p.lapse_rate_c_per_m * std::max(above, 0.0f);
  out.moisture = std::clamp(p.moisture_base + p.moisture_noise * nM - p.inland_drying_per_m * inland, 0.0f, 1.0f);
  return out;
}

LandCoverMasks landCoverMasks(const gpu::LandCoverParams& p, const LandCoverSite& site) {
  const ClimateSample climate = climateAt(p, site);
  const float above = static_cast<float>(site.elevation_m) - p.sea_level_m;
  const float slope =
      std::acos(std::clamp(static_cast<float>(site.cos_slope), 0.0f, 1.0f)) * (180.0f / std::numbers::pi_v<float>);
  std::array<float, kMaxLandCoverClasses> w{};
  float sum = 0.0f;
  for (gpu::uint i = 0; i < p.class_count; ++i) {
    const gpu::LandCoverClassParams& c = p.classes[i];
    w[i] = band(climate.temperature_c, c.temperature_min_c, c.temperature_max_c, p.temperature_blend_c) *
           band(climate.moisture, c.moisture_min, c.moisture_max, p.moisture_blend) *
           band(above, c.elevation_min_m, c.elevation_max_m, p.elevation_blend_m) *
           band(slope, c.slope_min_deg, c.slope_max_deg, p.slope_blend_deg);
    sum += w[i];
  }
  // Where no rule holds the first class covers the ground, blending in continuously.
  const float missing = std::max(1e-3f - sum, 0.0f);
  w[0] += missing;
  sum += missing;
  LandCoverMasks masks{};
  int total = 0, largest = 0;
  for (gpu::uint i = 0; i < p.class_count; ++i) {
    masks[i] = static_cast<std::uint8_t>(std::floor(w[i] / sum * 255.0f + 0.5f));
    total += masks[i];
    if (w[i] > w[largest]) largest = static_cast<int>(i);
  }
  masks[largest] = static_cast<std::uint8_t>(masks[largest] + (255 - total));
  return masks;
}

glm::vec3 landCoverAlbedo(const gpu::LandCoverParams& p, const LandCoverMasks& masks) {
  glm::vec3 albedo(0.0f);
  for (gpu::uint i = 0; i < p.class_count; ++i)
    albedo += (static_cast<float>(masks[i]) / 255.0f) * glm::vec3(p.classes[i].r, p.classes[i].g, p.classes[i].b);
  return albedo;
}

}  // namespace globe
