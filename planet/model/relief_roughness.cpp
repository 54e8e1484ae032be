#include "planet/model/relief_roughness.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "planet/lod/lod_ranges.h"

namespace globe {
namespace {

// A layer as the planet file states it, for layerValueBounds.
ElevationLayer describedLayer(const gpu::ElevationLayerParams& p) {
  ElevationLayer layer;
  layer.kind = static_cast<LayerKind>(p.kind);
  layer.octaves = static_cast<int>(p.octaves);
  layer.gain = p.gain;
  layer.amplitude_m = p.amplitude_m;
  return layer;
}

// The midpoint error of one layer's octaves at vertex spacing h (metres), unmodulated.
double layerError(const gpu::ElevationLayerParams& p, double h_m) {
  double error = 0.0;
  double wavelength = 1.0 / p.frequency;
  double amplitude = std::abs(p.amplitude_m);
  for (std::uint32_t o = 0; o < p.octaves; ++o) {
    error += amplitude * (1.0 - std::cos(std::min(std::numbers::pi, 2.0 * std::numbers::pi * h_m / wavelength)));
    wavelength /= p.lacunarity;
    amplitude *= std::abs(p.gain);
  }
  return error;
}

}  // namespace

std::shared_ptr<const RoughnessMap> reliefRoughnessMap(const ElevationModel& model, int gridCells, int maxDepth) {
  if (model.sources() != nullptr) return nullptr;
  const gpu::ElevationParams& params = model.params();
  const std::size_t layers = params.layer_count;
  const std::size_t depths = static_cast<std::size_t>(maxDepth) + 1;
  // Per depth: each layer's error and the sag, at the depth-(d+1) vertex spacing.
  std::vector<double> layerErrors(depths * layers);
  std::vector<double> sag(depths);
  const double radius = model.radius_m();
  for (std::size_t d = 0; d < depths; ++d) {
    const double h = nominalNodeWidth(static_cast<int>(d) + 1, radius) / gridCells;
    sag[d] = h * h / (2.0 * radius);
    for (std::size_t l = 0; l < layers; ++l) layerErrors[d * layers + l] = layerError(params.layers[l], h);
  }
  // A point is sea when even the highest its unevaluated layers can reach stays a margin below the
  // sea level (the margin covers coasts between grid points).
  std::vector<ElevationRange> bounds(layers);
  double margin = 0.0;
  for (std::size_t l = 0; l < layers; ++l) {
    bounds[l] = layerValueBounds(describedLayer(params.layers[l]));
    margin += 0.1 * (bounds[l].max_m - bounds[l].min_m);
  }
  const bool water = model.drawsWater();
  const double sea = model.seaLevel_m();
  const RoughnessMap::Model relief = [&](const glm::dvec3& direction, std::span<double> out) {
    const LayerModulation m = model.layerModulation(direction);
    double highest = 0.0;
    for (std::size_t l = 0; l < layers; ++l) {
      const double s = m.scale[l];
      highest +=
          m.value[l] ? *m.value[l] : params.layers[l].offset_m + std::max(s * bounds[l].min_m, s * bounds[l].max_m);
    }
    const bool underSea = water && highest + margin < sea;
    for (std::size_t d = 0; d < depths; ++d) {
      double e = sag[d];
      for (std::size_t l = 0; l < layers && !underSea; ++l) e += m.scale[l] * layerErrors[d * layers + l];
      out[d] = e;
    }
  };
  const double minRadius = model.shape().polarRadius_m() + std::min(0.0, model.bounds().min_m);
  return std::make_shared<const RoughnessMap>(RoughnessMap::build(maxDepth, minRadius, relief));
}

}  // namespace globe
