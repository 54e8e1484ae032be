#include "planet/model/elevation_model.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "planet/elevation/layer_evaluation.h"
#include "planet/sources/source_mosaic.h"
#include "planet/surface/surface_overlay.h"

namespace globe {

gpu::ElevationParams packElevationParams(const PlanetDescription& planet) {
  assert(validatePlanet(planet).ok());
  gpu::ElevationParams p{};
  p.radius_m = planet.radius_m;
  p.polar_radius_m = planetShape(planet).polarRadius_m();  // = radius_m on a sphere (a * (1 - 0))
  p.sea_level_m = planet.sea_level_m;
  p.layer_count = static_cast<gpu::uint>(planet.layers.size());
  for (std::size_t i = 0; i < planet.layers.size() && i < GLOBE_MAX_ELEVATION_LAYERS; ++i) {
    const ElevationLayer& l = planet.layers[i];
    gpu::ElevationLayerParams& g = p.layers[i];
    g.frequency = 1.0 / l.wavelength_m;
    g.lacunarity = l.lacunarity;
    g.gain = l.gain;
    g.amplitude_m = l.amplitude_m;
    g.offset_m = l.offset_m;
    g.seed = layerSeed(planet.seed, static_cast<int>(i));
    g.octaves = static_cast<gpu::uint>(l.octaves);
    g.kind = static_cast<gpu::uint>(l.kind);
    g.modulator = l.modulated_by >= 0 ? l.modulated_by : GLOBE_NO_MODULATOR;
    if (l.modulated_by >= 0) {
      g.modulation_low_m = l.modulation_low_m;
      g.modulation_inv_range = 1.0 / (l.modulation_high_m - l.modulation_low_m);
      g.modulation_floor = l.modulation_floor;
    } else {  // a scale of exactly 1, should the modulator ever be read
      g.modulation_floor = 1.0;
    }
  }
  return p;
}

ElevationModel::ElevationModel(const PlanetDescription& planet)
    : params_(packElevationParams(planet)),
      colourRamp_(packColourRamp(planet.colour_ramp)),
      landCover_(packLandCover(planet.land_cover, planet.radius_m, planet.seed, planet.sea_level_m)),
      landCoverDescription_(planet.land_cover),
      seed_(planet.seed),
      water_(planet.water),
      bounds_(elevationBounds(planet)),
      shape_(planetShape(planet)),
      atmosphere_(planet.atmosphere) {
  if (!planet.imagery.empty() || !planet.vectors.empty()) {
    overlay_ = std::make_shared<const SurfaceOverlay>(planet.imagery, planet.vectors, planet.radius_m);
    if (overlay_->empty()) overlay_.reset();
  }
  if (planet.sources.empty()) return;
  sources_ = std::make_shared<const SourceMosaic>(planet.sources, planet.radius_m, planet.seed);
  if (sources_->layers().empty()) return;
  // The mosaic mixes the two: the union of both ranges holds every blend.
  bounds_.min_m = std::min(bounds_.min_m, sources_->minElevation_m());
  bounds_.max_m = std::max(bounds_.max_m, sources_->maxElevation_m());
}

double ElevationModel::visibleElevation_m(const glm::dvec3& unit_direction) const {
  const double ground_m = elevation_m(unit_direction);
  return water_.enabled ? std::max(ground_m, params_.sea_level_m) : ground_m;
}

double ElevationModel::proceduralElevation_m(const glm::dvec3& unit_direction) const {
  return evaluateElevation<double>(params_, unit_direction.x, unit_direction.y, unit_direction.z);
}

SourceTerm ElevationModel::sourceTerm(const glm::dvec3& unit_direction, double sample_spacing_m) const {
  if (!sources_ || !sources_->mayCover(unit_direction)) return {};
  return sources_->term(unit_direction, sample_spacing_m);
}

double ElevationModel::elevation_m(const glm::dvec3& unit_direction) const {
  const double procedural = proceduralElevation_m(unit_direction);
  if (!sources_) return procedural;
  return combineSourceTerm(procedural, sourceTerm(unit_direction));
}

glm::dvec3 ElevationModel::surfacePosition(const glm::dvec3& unit_direction) const {
  return shape_.position(unit_direction, elevation_m(unit_direction));
}

double ElevationModel::heightAboveTerrain_m(const glm::dvec3& p, bool aboveWater) const {
  auto below = [&](const glm::dvec3& d) { return aboveWater ? visibleElevation_m(d) : elevation_m(d); };
  if (!shape_.isSphere()) {
    const GeodeticPoint g = shape_.geodeticFromGeocentric(p);
    return g.height_m - below(Ellipsoid::normalAt(g));
  }
  const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
  if (!(r > 0)) return -params_.radius_m;
  return r - params_.radius_m - below(p / r);
}

LayerModulation ElevationModel::layerModulation(const glm::dvec3& d) const {
  LayerModulation out;
  bool modulator[GLOBE_MAX_ELEVATION_LAYERS] = {};
  for (gpu::uint l = 0; l < params_.layer_count; ++l) {
    if (params_.layers[l].modulator >= 0) modulator[params_.layers[l].modulator] = true;
  }
  double values[GLOBE_MAX_ELEVATION_LAYERS] = {};
  const double radius = params_.radius_m;
  for (gpu::uint l = 0; l < params_.layer_count; ++l) {
    const gpu::ElevationLayerParams& layer = params_.layers[l];
    out.scale[l] = modulationScale(layer, values);
    if (!modulator[l]) continue;
    const double sum =
        octaveSum(layer, out.scale[l] == 0.0 ? 0U : layer.octaves, d.x * radius, d.y * radius, d.z * radius);
    values[l] = (layer.modulator >= 0 ? sum * out.scale[l] : sum) + layer.offset_m;
    out.value[l] = values[l];
  }
  return out;
}

double ElevationModel::firstLayer_m(const glm::dvec3& d) const {
  const gpu::ElevationLayerParams& layer = params_.layers[0];
  const double radius = params_.radius_m;
  return octaveSum(layer, layer.octaves, d.x * radius, d.y * radius, d.z * radius) + layer.offset_m;
}

float ElevationModel::elevationFloat_m(const glm::vec3& unit_direction) const {
  return evaluateElevation<float>(params_, unit_direction.x, unit_direction.y, unit_direction.z);
}

}  // namespace globe
