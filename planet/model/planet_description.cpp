#include "planet/model/planet_description.h"

#include "planet/core/finite_range.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

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

ElevationRange elevationBounds(const PlanetDescription& planet) { return layersBounds(planet.layers); }

namespace {

Error fieldError(std::string field, std::string message) {
  return Error::inField(std::move(field), std::move(message));
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
  for (std::size_t i = 0; i < planet.layers.size(); ++i)
    appendLayerErrors(planet.layers, i, planet.radius_m, radius_ok, errors);
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

}  // namespace globe
