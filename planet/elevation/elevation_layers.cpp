#include "planet/elevation/elevation_layers.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "planet/core/finite_range.h"
#include "planet/core/gradient_noise.h"
#include "planet/elevation/crater_field.h"

namespace globe {

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

int maxOctavesForPrecision(double radius_m, const ElevationLayer& layer) {
  double wavelength = layer.wavelength_m;
  int octaves = 0;
  while (octaves < kMaxOctavesPerLayer && radius_m / wavelength <= kMaxLatticeCoordinate) {
    ++octaves;
    wavelength /= layer.lacunarity;
  }
  return octaves;
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

ElevationRange layersBounds(const std::vector<ElevationLayer>& layers) {
  ElevationRange total;
  for (const ElevationLayer& layer : layers) {
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

void appendLayerErrors(const std::vector<ElevationLayer>& layers, std::size_t i, double radius_m, bool radius_ok,
                       std::vector<Error>& errors) {
  auto fail = [&errors](std::string field, std::string message) {
    errors.push_back(Error::inField(std::move(field), std::move(message)));
  };
  const ElevationLayer& l = layers[i];
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
  if (radius_ok && octaves_ok && !(radius_m / finest <= kMaxLatticeCoordinate)) {
    fail(p + "octaves", fmt::format("too many octaves for double precision at this radius: finest "
                                    "wavelength {:g} m, radius / wavelength must be <= 2^40 (at most {} "
                                    "octaves here)",
                                    finest, maxOctavesForPrecision(radius_m, l)));
  }
  for (std::size_t j = 0; j < i; ++j) {
    if (layers[j].name == l.name) {
      fail(p + "name", fmt::format("duplicate layer name '{}'", l.name));
      break;
    }
  }
}

}  // namespace globe
