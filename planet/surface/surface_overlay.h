#pragma once
// What a planet's imagery ([[imagery]], imagery_mosaic.h) and vector layers ([[vectors]],
// planet/vectors/vector_overlay.h) paint over the procedural albedo: the colour the payloads'
// surface carries per vertex and per texel (docs/imagery.md). The vectors lie over the imagery. The
// source I/O thread resolves it per generation job at the job's mesh samples and surface texture
// lattice (request_preparer.h); the payload kernel blends it over the albedo of the colour ramp or
// the land cover, so it costs nothing per frame.
#include "planet/sources/imagery_mosaic.h"
#include "planet/vectors/vector_overlay.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace globe {

// Screen pixels a surface texel is taken to cover when a vector layer's width is given in pixels
// (width_m = width_px * texel_m / this): the payloads are made once for every view, and the LOD's
// texel rule keeps a texel near this size on screen (docs/imagery.md, "Vectors").
inline constexpr double kScreenPixelsPerTexel = 4.0;

// The overlay at a point: `land`, the imagery with the vectors over it, is what the ground shows;
// `vectors`, the vector layers' own colour and coverage, is what the sea shows (the water shader
// draws the sea over the imagery, the vectors over the sea).
struct SurfaceColour {
  ImageryColour land;
  ImageryColour vectors;
};

class SurfaceOverlay {
 public:
  SurfaceOverlay(const std::vector<ImagerySource>& imagery, const std::vector<VectorLayer>& vectors, double radius_m);
  ~SurfaceOverlay();

  // Nothing to paint (no layer opened).
  bool empty() const;
  // Some vector layer draws something (they are drawn into surface textures only: overlaidAlbedo).
  bool hasVectors() const;
  // The overlay's linear colour and coverage at a direction, for a surface texel of `texel_m` metres
  // (> 0 where vector layers are painted: their antialiasing filter). `withVectors` false: the
  // imagery alone (a vertex, or a node vectorsMayTouch ruled out).
  SurfaceColour colourAt(const glm::dvec3& unitDirection, double texel_m, bool withVectors = true) const;
  // False when no vector feature can reach any of `directions` (a node's samples) for texels of up
  // to `texel_m` metres: its points need no vector query.
  bool vectorsMayTouch(std::span<const glm::dvec3> directions, double texel_m) const;

  const ImageryMosaic& imagery() const { return imagery_; }

 private:
  ImageryMosaic imagery_;
  std::unique_ptr<VectorOverlay> vectors_;
  double widestPx_ = 0.0;  // the widest line or marker given in pixels
};

// The overlay colour as the payload kernel reads it (payload_generate.glsl, `overlaid`): the square
// root of the linear albedo in bytes 0-2 (as the payload's surface word, payload_surface.glsl),
// coverage in byte 3.
std::uint32_t packOverlayColour(const ImageryColour& c);
ImageryColour unpackOverlayColour(std::uint32_t word);

// A vertex's `albedo` under the overlay's imagery at a direction as the payload kernel blends it (the
// packed word's 8 bits, then mix(albedo, colour, coverage) in float): the CPU references' mirror.
// Vectors are left out: they are drawn into the surface textures alone, since a vertex would widen a
// line to its cell and smear it across the triangles. `overlay` nullptr: `albedo` unchanged.
glm::vec3 overlaidAlbedo(const SurfaceOverlay* overlay, const glm::vec3& albedo, const glm::dvec3& unitDirection,
                         double texel_m);
// A surface texel under the overlay, from one overlay query: its overlaid albedo (overlaidAlbedo)
// and the colour layer's texel (payload_generate.glsl, colourLayerTexel) before its 8-bit store:
// where vectors cover a texel whose ground lies below the drawn sea, their own colour (the water
// fragments mix it over the water by its coverage); elsewhere the overlaid albedo; alpha the
// vectors' coverage (its 8 bits). Without an overlay (albedo, (albedo, 0)).
struct OverlaidTexel {
  glm::vec3 albedo;
  glm::vec4 colourLayer;
};
OverlaidTexel overlaidTexel(const SurfaceOverlay* overlay, const glm::vec3& albedo, const glm::dvec3& unitDirection,
                            double texel_m, bool underSea);

}  // namespace globe
