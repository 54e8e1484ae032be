#include "planet/elevation/planet_description.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

#include "planet/elevation/crater_field.h"
#include "planet/elevation/gradient_noise.h"

namespace globe {

std::string_view qualityPresetName(QualityPreset preset) {
  switch (preset) {
    case QualityPreset::kFast:
      return "fast";
    case QualityPreset::kBalanced:
      return "balanced";
    case QualityPreset::kExact:
      return "exact";
  }
  return "unknown";
}

std::optional<QualityPreset> qualityPresetFromName(std::string_view name) {
  for (QualityPreset p : {QualityPreset::kFast, QualityPreset::kBalanced, QualityPreset::kExact})
    if (qualityPresetName(p) == name) return p;
  return std::nullopt;
}

std::string_view layerKindName(LayerKind kind) {
  switch (kind) {
    case LayerKind::kFbm:
      return "fbm";
    case LayerKind::kRidged:
      return "ridged";
    case LayerKind::kBillow:
      return "billow";
    case LayerKind::kCraters:
      return "craters";
  }
  return "unknown";
}

double finestWavelength_m(const ElevationLayer& layer) {
  double wavelength = layer.wavelength_m;
  for (int i = 1; i < layer.octaves; ++i) wavelength /= layer.lacunarity;
  return wavelength;
}

namespace {

// Sum of the octave amplitudes, metres (amplitude_m * (1 + gain + gain^2 + ...)).
double amplitudeSum(const ElevationLayer& layer) {
  double sum = 0.0;
  double amplitude = layer.amplitude_m;
  for (int i = 0; i < layer.octaves; ++i) {
    sum += std::abs(amplitude);
    amplitude *= layer.gain;
  }
  return sum;
}

}  // namespace

ElevationRange layerValueBounds(const ElevationLayer& layer) {
  const double sum = amplitudeSum(layer);
  ElevationRange r;
  switch (layer.kind) {
    case LayerKind::kFbm:
      r = {-sum * kGradientNoiseBound, sum * kGradientNoiseBound};
      break;
    case LayerKind::kRidged:  // (1 - |n|)^2 <= max(1, (1 - bound)^2) = 1
      r = {0.0, sum};
      break;
    case LayerKind::kBillow:
      r = {0.0, sum * kGradientNoiseBound};
      break;
    case LayerKind::kCraters:
      r = {sum * kCraterFieldMin, sum * kCraterFieldMax};
      break;
  }
  return r;
}

ElevationRange elevationBounds(const PlanetDescription& planet) {
  ElevationRange total;
  for (const ElevationLayer& layer : planet.layers) {
    ElevationRange r = layerValueBounds(layer);
    if (layer.modulated_by >= 0) {  // scale in [floor, 1]
      const double f = layer.modulation_floor;
      r = {std::min(r.min_m, r.min_m * f), std::max(r.max_m, r.max_m * f)};
    }
    total.min_m += r.min_m + layer.offset_m;
    total.max_m += r.max_m + layer.offset_m;
  }
  // Margin for the rounding of the evaluation itself (~1e-12 relative).
  const double margin = 1e-9 * (std::abs(total.min_m) + std::abs(total.max_m)) + 1e-6;
  total.min_m -= margin;
  total.max_m += margin;
  return total;
}

namespace {

bool inRange(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

Error fieldError(std::string field, std::string message) {
  return Error::inField(std::move(field), std::move(message));
}

// The errors of layer `i` (its fields, the precision rule once the radius is valid, a duplicate name).
void appendLayerErrors(const PlanetDescription& planet, std::size_t i, bool radius_ok, std::vector<Error>& errors) {
  auto fail = [&errors](std::string field, std::string message) {
    errors.push_back(fieldError(std::move(field), std::move(message)));
  };
  const ElevationLayer& l = planet.layers[i];
  const std::string p = fmt::format("layers[{}].", i);
  bool octaves_ok = true;
  if (l.octaves < 1 || l.octaves > kMaxOctavesPerLayer) {
    fail(p + "octaves", fmt::format("must be in [1, {}]", kMaxOctavesPerLayer));
    octaves_ok = false;
  }
  if (!(std::isfinite(l.wavelength_m) && l.wavelength_m > 0.0)) {
    fail(p + "wavelength_m", "must be finite and > 0");
    octaves_ok = false;
  }
  if (!(std::isfinite(l.lacunarity) && l.lacunarity > 1.0 && l.lacunarity <= 16.0)) {
    fail(p + "lacunarity", "must be > 1 and <= 16");
    octaves_ok = false;
  }
  if (!(std::isfinite(l.gain) && l.gain > 0.0 && l.gain <= 1.0)) fail(p + "gain", "must be > 0 and <= 1");
  if (!inRange(l.amplitude_m, 0.0, 1e6)) fail(p + "amplitude_m", "must be within [0, 1e6] m");
  if (!inRange(l.offset_m, -1e6, 1e6)) fail(p + "offset_m", "must be within [-1e6, 1e6] m");
  if (l.modulated_by >= static_cast<int>(i) || l.modulated_by < -1) {
    fail(p + "modulated_by", "must name an earlier layer");
  }
  if (l.modulated_by >= 0) {
    if (!inRange(l.modulation_low_m, -1e7, 1e7)) fail(p + "modulation_low_m", "must be within [-1e7, 1e7] m");
    if (!inRange(l.modulation_high_m, -1e7, 1e7) || !(l.modulation_high_m > l.modulation_low_m)) {
      fail(p + "modulation_high_m", "must be > modulation_low_m and within [-1e7, 1e7] m");
    }
    if (!inRange(l.modulation_floor, 0.0, 1.0)) fail(p + "modulation_floor", "must be within [0, 1]");
  }
  // The precision rule only means something once the radius and the octave chain are valid.
  const double finest = octaves_ok ? finestWavelength_m(l) : 1.0;
  if (radius_ok && octaves_ok && !(planet.radius_m / finest <= kMaxLatticeCoordinate)) {
    fail(p + "octaves", fmt::format("too many octaves for double precision at this radius: finest "
                                    "wavelength {:g} m, radius / wavelength must be <= 2^40 (at most {} "
                                    "octaves here)",
                                    finest, maxOctavesForPrecision(planet.radius_m, l)));
  }
  for (std::size_t j = 0; j < i; ++j) {
    if (planet.layers[j].name == l.name) {
      fail(p + "name", fmt::format("duplicate layer name '{}'", l.name));
      break;
    }
  }
}

}  // namespace

std::vector<Error> validatePlanetAll(const PlanetDescription& planet) {
  std::vector<Error> errors;
  auto fail = [&errors](std::string field, std::string message) {
    errors.push_back(fieldError(std::move(field), std::move(message)));
  };
  const bool radius_ok = std::isfinite(planet.radius_m) && planet.radius_m > 0.0 && planet.radius_m <= kMaxRadius_m;
  if (!radius_ok) fail("radius_m", fmt::format("must be > 0 and <= {:g} m", kMaxRadius_m));
  if (!(std::isfinite(planet.flattening) && planet.flattening >= 0.0 && planet.flattening < kMaxFlattening)) {
    fail("flattening", fmt::format("must be in [0, {:g})", kMaxFlattening));
  }
  if (!inRange(planet.sea_level_m, -1e6, 1e6)) fail("sea_level_m", "must be finite and within [-1e6, 1e6] m");
  if (!(std::isfinite(planet.surface_gravity_m_s2) && planet.surface_gravity_m_s2 > 0.0 &&
        planet.surface_gravity_m_s2 <= 1e4)) {
    fail("surface_gravity_m_s2", "must be > 0 and <= 1e4 m/s^2");
  }
  if (planet.layers.empty() || planet.layers.size() > static_cast<std::size_t>(kMaxElevationLayers)) {
    fail("layers", fmt::format("need 1 to {} layers", kMaxElevationLayers));
  }
  for (std::size_t i = 0; i < planet.layers.size(); ++i) appendLayerErrors(planet, i, radius_ok, errors);
  appendColourRampErrors(planet.colour_ramp, errors);
  appendWaterErrors(planet.water, errors);
  appendLandCoverErrors(planet.land_cover, errors);
  if (planet.atmosphere) {
    std::vector<Error> atmosphere = validateAtmosphere(*planet.atmosphere, radius_ok ? planet.radius_m : 1e6);
    errors.insert(errors.end(), std::make_move_iterator(atmosphere.begin()), std::make_move_iterator(atmosphere.end()));
  }
  return errors;
}

Status validatePlanet(const PlanetDescription& planet) {
  std::vector<Error> errors = validatePlanetAll(planet);
  if (!errors.empty()) return std::move(errors.front());
  return Ok{};
}

Ellipsoid planetShape(const PlanetDescription& planet) {
  return Ellipsoid::create(planet.radius_m, planet.flattening).value();
}

std::optional<Error> terrainReachesCentre(const PlanetDescription& planet) {
  const ElevationRange range = elevationBounds(planet);
  if (planet.flattening == 0.0) {
    if (range.min_m > -planet.radius_m) return std::nullopt;
    return fieldError("layers", fmt::format("the layers can reach {:g} m, deeper than radius_m = {:g} m: lower the "
                                            "amplitudes or offsets",
                                            range.min_m, planet.radius_m));
  }
  // On an ellipsoid the node bounds need every surface point farther from the centre than the largest
  // offset of p(n) from its normal line (LodSelector::create checks the same).
  const Ellipsoid shape = planetShape(planet);
  double axisMin = 0.0, axisMax = 0.0;
  shape.axisOffsetRange_m(0.0, 1.0, axisMin, axisMax);
  const double deepest_m = axisMax * (1.0 + 1e-9) - shape.polarRadius_m();
  if (range.min_m > deepest_m) return std::nullopt;
  return fieldError("layers", fmt::format("the layers can reach {:g} m, deeper than {:g} m, the limit of this "
                                          "ellipsoid (polar radius minus its largest normal offset): lower the "
                                          "amplitudes or offsets, or the flattening",
                                          range.min_m, deepest_m));
}

int maxOctavesForPrecision(double radius_m, const ElevationLayer& layer) {
  double wavelength = layer.wavelength_m;
  int octaves = 0;
  while (octaves < kMaxOctavesPerLayer && radius_m / wavelength <= kMaxLatticeCoordinate) {
    ++octaves;
    wavelength /= layer.lacunarity;
  }
  return octaves;
}

}  // namespace globe
