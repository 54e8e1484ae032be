#pragma once
// What a planet's imagery ([[imagery]], imagery_mosaic.h) paints over the procedural albedo: the
// colour the payloads' surface carries per vertex and per texel (docs/imagery.md). The source I/O
// thread resolves it per generation job at the job's mesh samples and surface texture lattice
// (request_preparer.h); the payload kernel blends it over the albedo of the colour ramp or the land
// cover, so it costs nothing per frame.
#include "planet/sources/imagery_mosaic.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace globe {

class SurfaceOverlay {
 public:
  SurfaceOverlay(const std::vector<ImagerySource>& imagery, double radius_m);

  // Nothing to paint (no layer opened).
  bool empty() const;
  // The overlay's linear colour and coverage at a direction, for a surface texel of `texel_m` metres.
  ImageryColour colourAt(const glm::dvec3& unitDirection, double texel_m) const;

  const ImageryMosaic& imagery() const { return imagery_; }

 private:
  ImageryMosaic imagery_;
};

// The overlay colour as the payload kernel reads it (payload_overlay.glsl): the square root of the
// linear albedo in bytes 0-2 (as the payload's surface word, payload_surface.glsl), coverage in byte 3.
std::uint32_t packOverlayColour(const ImageryColour& c);
ImageryColour unpackOverlayColour(std::uint32_t word);

// `albedo` under the overlay's colour at a direction as the payload kernel blends it (the packed
// word's 8 bits, then mix(albedo, colour, coverage) in float): the CPU references' mirror.
// `overlay` nullptr: `albedo` unchanged.
glm::vec3 overlaidAlbedo(const SurfaceOverlay* overlay, const glm::vec3& albedo, const glm::dvec3& unitDirection,
                         double texel_m);

}  // namespace globe
