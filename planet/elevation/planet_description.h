#pragma once
// What a planet is: radius, seed, sea level and the elevation layers. Read from a TOML planet file
// (planet/elevation/planet_file.h); assets/planets/earthlike.toml is the default planet. Units are metres.
//
// Elevation model (docs/elevation.md): the elevation at a unit direction d is the sum of the layers'
// values, each an fBm-like sum of octaves of 3-D gradient noise evaluated at the point d * radius_m
// (so there are no seams and no polar artefacts). A layer may be *modulated* by an earlier layer:
// its octave sum is scaled by a smooth mask of the modulator's value (mountains only where the
// continents are high) — the 4 continent octaves modulating 8 detail octaves of [Frasson 2018].
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "planet/atmosphere/atmosphere_parameters.h"
#include "planet/core/error.h"
#include "planet/elevation/colour_ramp.h"
#include "planet/geometry/ellipsoid.h"
#include "planet/sources/imagery_source.h"
#include "planet/sources/source_description.h"
#include "planet/surface/land_cover.h"
#include "planet/vectors/vector_layer.h"

namespace globe {

enum class LayerKind : std::uint32_t {
  kFbm = 0,      // sum amp_i * n_i
  kRidged = 1,   // sum amp_i * (1 - |n_i|)^2 (crests where n = 0; >= 0)
  kBillow = 2,   // sum amp_i * |n_i| (>= 0)
  kCraters = 3,  // sum amp_i * craters_i (impact craters, planet/elevation/crater_field.h)
};

// "fbm", "ridged", "billow", "craters".
std::string_view layerKindName(LayerKind kind);

// The speed/accuracy trade a planet is meant to be viewed at by default (the renderer and
// `globe trade` interpret it; stored and validated here).
enum class QualityPreset : std::uint32_t { kFast = 0, kBalanced = 1, kExact = 2 };

// "fast", "balanced", "exact".
std::string_view qualityPresetName(QualityPreset preset);
// The inverse of qualityPresetName; nullopt for any other text. The one parser of quality names.
std::optional<QualityPreset> qualityPresetFromName(std::string_view name);

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
inline constexpr double kMaxRadius_m = 1.0e9;  // 7e7 m (a gas giant) is the largest preset
// Flattening must stay below this (b > a / 2); WGS84's is 1 / 298.257223563.
inline constexpr double kMaxFlattening = 0.5;
// Largest lattice coordinate (radius * finest frequency) allowed: keeps the noise's cell offset
// exact to 2^-12 cells in double and the 64-bit lattice index far from overflow.
inline constexpr double kMaxLatticeCoordinate = 1099511627776.0;  // 2^40

struct PlanetDescription {
  std::string name = "unnamed";
  double radius_m =
      6371000.0;  // sphere radius, or the ellipsoid's equatorial radius a (elevation 0), metres, (0, kMaxRadius_m]
  // (a - b) / a of the reference ellipsoid (planet/geometry/ellipsoid.h), [0, kMaxFlattening); 0 = a sphere
  // of radius_m. Elevation is the ellipsoidal height along the geodetic normal. In a file: `shape`.
  double flattening = 0.0;
  std::uint64_t seed = 0;              // noise seed; every layer derives its own from it
  double sea_level_m = 0.0;            // elevation of the sea surface, metres (stats; drawn with [water])
  std::vector<ElevationLayer> layers;  // 1 .. kMaxElevationLayers, evaluated in order
  double surface_gravity_m_s2 = 9.81;  // gravity at radius_m (physics, falling as 1/r^2), (0, 1e4]
  QualityPreset default_quality = QualityPreset::kBalanced;
  ColourRamp colour_ramp;  // surface colour by elevation and slope
  Water water;             // the sea drawn at sea_level_m ([water]); disabled = a dry planet
  // [climate] and [[land_cover]]: classes that colour the ground instead of the ramp (planet/surface/).
  LandCover land_cover;
  // Real elevation rasters mosaicked over the layers ([[sources]], planet/sources/); empty = procedural only.
  std::vector<ElevationSource> sources;
  // Colour rasters draped over the ground's albedo ([[imagery]], planet/sources/imagery_mosaic.h).
  std::vector<ImagerySource> imagery;
  // Vector data painted over it ([[vectors]], planet/vectors/vector_overlay.h).
  std::vector<VectorLayer> vectors;
  // [atmosphere]: precomputed scattering (docs/rendering.md, "Atmosphere"); none = black sky.
  std::optional<AtmosphereParameters> atmosphere;

  bool operator==(const PlanetDescription&) const = default;
};

// Conservative elevation range, metres: every elevation the model can produce lies in [min_m, max_m]
// (from the amplitudes and kGradientNoiseBound, not from sampling). LOD bounds start from it.
struct ElevationRange {
  double min_m = 0.0;
  double max_m = 0.0;
};
ElevationRange elevationBounds(const PlanetDescription& planet);
// The range of one layer's octave sum before its modulation scale and offset (same rules).
ElevationRange layerValueBounds(const ElevationLayer& layer);

// The planet's reference surface: Ellipsoid::create(radius_m, flattening); `planet` must be valid.
Ellipsoid planetShape(const PlanetDescription& planet);

// Wavelength of a layer's last (finest) octave, metres.
double finestWavelength_m(const ElevationLayer& layer);

// Most octaves `layer` may have at `radius_m` under the precision rule (radius / finest wavelength
// <= kMaxLatticeCoordinate), capped at kMaxOctavesPerLayer; 0 when even the first is too fine.
int maxOctavesForPrecision(double radius_m, const ElevationLayer& layer);

// Checks every value's range and the cross-field rules (modulator earlier than the layer, precision
// limit radius / finest wavelength <= kMaxLatticeCoordinate, colour ramp stops increasing). Each
// Error has field set (e.g. "layers[1].gain") but no file position; the planet file loader adds
// positions itself. Returns every problem, in field order; empty when the planet is valid.
std::vector<Error> validatePlanetAll(const PlanetDescription& planet);

// The first problem of validatePlanetAll, or Ok.
Status validatePlanet(const PlanetDescription& planet);

// An authoring rule, checked by the planet file loader but not by validatePlanet (numerical tests
// deliberately put Earth's layers on a 1 km sphere): the conservative low bound must stay above
// -radius_m, or the surface would pass through the centre. `planet` must be valid.
std::optional<Error> terrainReachesCentre(const PlanetDescription& planet);

}  // namespace globe
