#pragma once
// What a planet is: radius, shape, seed, sea level, the elevation layers (planet/elevation/), the real
// rasters and vectors over them (planet/sources/, planet/vectors/), the surface's colours
// (planet/surface/) and the air (planet/atmosphere/). Read from a TOML planet file
// (planet/model/planet_file.h); assets/planets/earthlike.toml is the default planet. Units are metres.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "planet/atmosphere/atmosphere_parameters.h"
#include "planet/core/error.h"
#include "planet/elevation/elevation_layers.h"
#include "planet/geometry/ellipsoid.h"
#include "planet/sources/imagery_source.h"
#include "planet/sources/source_description.h"
#include "planet/surface/colour_ramp.h"
#include "planet/surface/land_cover.h"
#include "planet/vectors/vector_layer.h"

namespace globe {

// The speed/accuracy trade a planet is meant to be viewed at by default (the renderer and
// `globe trade` interpret it; stored and validated here).
enum class QualityPreset : std::uint32_t { kFast = 0, kBalanced = 1, kExact = 2 };

// "fast", "balanced", "exact".
std::string_view qualityPresetName(QualityPreset preset);
// The inverse of qualityPresetName; nullopt for any other text. The one parser of quality names.
std::optional<QualityPreset> qualityPresetFromName(std::string_view name);

inline constexpr double kMaxRadius_m = 1.0e9;  // 7e7 m (a gas giant) is the largest preset
// Flattening must stay below this (b > a / 2); WGS84's is 1 / 298.257223563.
inline constexpr double kMaxFlattening = 0.5;

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

// Conservative range of the planet's elevation, metres (layersBounds of its layers): every elevation
// the model can produce lies in it. LOD bounds start from it.
ElevationRange elevationBounds(const PlanetDescription& planet);

// The planet's reference surface: Ellipsoid::create(radius_m, flattening); `planet` must be valid.
Ellipsoid planetShape(const PlanetDescription& planet);

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
