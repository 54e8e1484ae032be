#pragma once
// The procedural elevation layers (docs/elevation.md): each an fBm-like sum of octaves of 3-D gradient
// noise (or of crater fields) evaluated at the point d * radius_m, optionally *modulated* by an earlier
// layer (mountains only where the continents are high: the continent octaves modulating the detail
// octaves of [Frasson 2018]). What a layer is, its value bounds and its validation rules; the planet
// model (planet/model/planet_description.h) holds a list of them.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "planet/core/error.h"

namespace globe {

enum class LayerKind : std::uint32_t {
  kFbm = 0,      // sum amp_i * n_i
  kRidged = 1,   // sum amp_i * (1 - |n_i|)^2 (crests where n = 0; >= 0)
  kBillow = 2,   // sum amp_i * |n_i| (>= 0)
  kCraters = 3,  // sum amp_i * craters_i (impact craters, planet/elevation/crater_field.h)
};

// "fbm", "ridged", "billow", "craters".
std::string_view layerKindName(LayerKind kind);

// One layer: `octaves` octaves of gradient noise; octave i has wavelength wavelength_m / lacunarity^i
// and amplitude amplitude_m * gain^i.
struct ElevationLayer {
  std::string name;  // unique within the planet, used by modulated_by
  LayerKind kind = LayerKind::kFbm;
  int octaves = 1;              // 1 .. kMaxOctavesPerLayer
  double wavelength_m = 1.0e6;  // wavelength of the first octave, metres (> 0)
  double lacunarity = 2.0;      // frequency ratio between octaves, (1, 16]
  double gain = 0.5;            // amplitude ratio between octaves, (0, 1]
  double amplitude_m = 1000.0;  // amplitude of the first octave, metres, [0, 1e6]
  double offset_m = 0.0;        // constant added to the layer after modulation, metres
  int modulated_by = -1;        // index of an earlier layer, or -1 (not modulated)
  // Mask m = smoothstep((value(modulated_by) - low) / (high - low)); the octave sum is scaled by
  // floor + (1 - floor) * m. Ignored when modulated_by < 0.
  double modulation_low_m = 0.0;      // modulator value (m) where the mask is 0
  double modulation_high_m = 1000.0;  // modulator value (m) where the mask is 1 (> low)
  double modulation_floor = 0.0;      // scale where the mask is 0, [0, 1]

  bool operator==(const ElevationLayer&) const = default;
};

inline constexpr int kMaxElevationLayers = 8;  // = GLOBE_MAX_ELEVATION_LAYERS (GPU struct size)
inline constexpr int kMaxOctavesPerLayer = 24;
// Largest lattice coordinate (radius * finest frequency) allowed: keeps the noise's cell offset
// exact to 2^-12 cells in double and the 64-bit lattice index far from overflow.
inline constexpr double kMaxLatticeCoordinate = 1099511627776.0;  // 2^40

// Conservative elevation range, metres: every value lies in [min_m, max_m] (from the amplitudes and
// kGradientNoiseBound, not from sampling). LOD bounds start from it.
struct ElevationRange {
  double min_m = 0.0;
  double max_m = 0.0;
};
// The range of one layer's octave sum before its modulation scale and offset.
ElevationRange layerValueBounds(const ElevationLayer& layer);
// The range of the layers' sum, modulation and offsets included, with a margin for rounding.
ElevationRange layersBounds(const std::vector<ElevationLayer>& layers);

// Wavelength of a layer's last (finest) octave, metres.
double finestWavelength_m(const ElevationLayer& layer);

// Most octaves `layer` may have at `radius_m` under the precision rule (radius / finest wavelength
// <= kMaxLatticeCoordinate), capped at kMaxOctavesPerLayer; 0 when even the first is too fine.
int maxOctavesForPrecision(double radius_m, const ElevationLayer& layer);

// Appends the errors of layers[i] (fields "layers[i].*"): its values, the precision rule at
// `radius_m` (skipped when `radius_ok` is false) and a name already used by an earlier layer.
void appendLayerErrors(const std::vector<ElevationLayer>& layers, std::size_t i, double radius_m, bool radius_ok,
                       std::vector<Error>& errors);

}  // namespace globe
