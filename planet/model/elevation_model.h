#pragma once
// The planet's elevation on the CPU: the procedural layers (planet/elevation/layer_evaluation.h, the
// reference the GPU kernels mirror to <= 1e-6 m) with the planet's real sources mosaicked over them,
// over its reference surface (on an ellipsoid: elevation is a function of the geodetic normal; the noise
// point stays d * radius_m). Also what the renderer reads of the planet: sea, colours, land cover, air.
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>

#include "planet/elevation/layer_evaluation.h"
#include "planet/model/planet_description.h"
#include "shaders/include/elevation_params.h"

namespace globe {

class SourceMosaic;
class SurfaceOverlay;
struct SourceTerm;

// Packs a (valid, see validatePlanet) description into the struct the shaders read; unused layer
// slots are zero. frequency = 1 / wavelength_m, modulation_inv_range = 1 / (high - low).
gpu::ElevationParams packElevationParams(const PlanetDescription& planet);

// What modulates each layer at a direction (ElevationModel::layerModulation): the scale its octave
// sum is multiplied by (1 without modulator) and, for the layers that modulate others, their value
// (metres; nullopt for the layers not evaluated).
struct LayerModulation {
  std::array<double, GLOBE_MAX_ELEVATION_LAYERS> scale{};
  std::array<std::optional<double>, GLOBE_MAX_ELEVATION_LAYERS> value{};
};

class ElevationModel {
 public:
  // `planet` must be valid (validatePlanet); checked by assert.
  explicit ElevationModel(const PlanetDescription& planet);

  // Elevation above radius_m at a unit direction, metres. |unit_direction| = 1 is the caller's job
  // (the result scales with the point d * radius_m). With sources, the mosaic over the layers
  // (combineSourceTerm, planet/sources/source_mosaic.h).
  double elevation_m(const glm::dvec3& unit_direction) const;
  // The procedural layers alone (what the GPU kernels evaluate themselves).
  double proceduralElevation_m(const glm::dvec3& unit_direction) const;
  // What the planet's sources contribute at a direction (weight 0 without sources), read at the
  // pyramid level that samples `sample_spacing_m` apart resolve (0: full resolution;
  // SourceMosaic::term).
  SourceTerm sourceTerm(const glm::dvec3& unit_direction, double sample_spacing_m = 0.0) const;
  // The mosaic of the planet's [[sources]], or nullptr for a procedural planet.
  const SourceMosaic* sources() const { return sources_.get(); }
  // What the planet's [[imagery]] and [[vectors]] paint over the albedo, or nullptr when it has none.
  const SurfaceOverlay* overlay() const { return overlay_.get(); }
  // The terrain point over a unit geodetic normal: shape().position(unit_direction, elevation_m), metres,
  // planet-centred; on a sphere unit_direction * (radius_m + elevation_m).
  glm::dvec3 surfacePosition(const glm::dvec3& unit_direction) const;
  // Height of a planet-fixed point above the terrain below it (metres, negative inside): on a sphere
  // |p| - radius_m - elevation_m(p / |p|); on an ellipsoid the ellipsoidal height minus the elevation
  // at the geodetic normal below p (GeographicLib).
  // `aboveWater`: above the visible surface (visibleElevation_m) instead of the ground.
  double heightAboveTerrain_m(const glm::dvec3& position_m, bool aboveWater = false) const;
  // The procedural layers' modulation at a direction; evaluates only the modulating layers' octaves
  // (where the terrain is rough: planet/model/relief_roughness.h).
  LayerModulation layerModulation(const glm::dvec3& unit_direction) const;
  // The value of the planet's first (continental) layer at a direction, metres: what the land
  // cover's climate reads as the distance inland (planet/surface/land_cover.h).
  double firstLayer_m(const glm::dvec3& unit_direction) const;
  // The same evaluation carried out entirely in float (radius, point, frequencies, noise): only to
  // measure what double buys (docs/elevation.md); never use it for geometry.
  float elevationFloat_m(const glm::vec3& unit_direction) const;

  // The sphere's radius, or the ellipsoid's equatorial radius (metres).
  double radius_m() const { return params_.radius_m; }
  // The reference surface elevations are heights above (along its geodetic normals).
  const Ellipsoid& shape() const { return shape_; }
  // The planet's [atmosphere], if it has one (kept here for the renderer; elevation ignores it).
  const std::optional<AtmosphereParameters>& atmosphere() const { return atmosphere_; }
  double seaLevel_m() const { return params_.sea_level_m; }
  // The planet has a sea ([water]): the renderer draws a water surface at sea level over lower ground.
  bool drawsWater() const { return water_.enabled; }
  const Water& water() const { return water_; }
  // Elevation of the surface a viewer sees (metres): the ground, or the sea surface above lower ground
  // on a planet with water. Cameras placed "above the terrain" stand above this one.
  double visibleElevation_m(const glm::dvec3& unit_direction) const;
  const gpu::ElevationParams& params() const { return params_; }
  // The surface colour by elevation and slope (the planet's colour ramp), as the payload kernel
  // reads it: each payload sample carries its albedo (shaders/include/payload_layout.h).
  const gpu::ColourRampParams& colourRamp() const { return colourRamp_; }
  // The land cover as the payload kernel reads it (class_count 0: none, the colour ramp colours).
  const gpu::LandCoverParams& landCover() const { return landCover_; }
  // The planet file's land cover (for its detail textures) and seed.
  const LandCover& landCoverDescription() const { return landCoverDescription_; }
  std::uint64_t seed() const { return seed_; }
  // Conservative range of elevation_m (see elevationBounds).
  ElevationRange bounds() const { return bounds_; }

 private:
  gpu::ElevationParams params_{};
  gpu::ColourRampParams colourRamp_{};
  gpu::LandCoverParams landCover_{};
  LandCover landCoverDescription_;
  std::uint64_t seed_ = 0;
  Water water_;
  ElevationRange bounds_{};
  Ellipsoid shape_;
  std::shared_ptr<const SourceMosaic> sources_;  // shared by copies
  std::shared_ptr<const SurfaceOverlay> overlay_;
  std::optional<AtmosphereParameters> atmosphere_;
};

}  // namespace globe
