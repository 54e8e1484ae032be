#pragma once
// The mosaic of a planet's imagery (docs/imagery.md): at a unit direction, the colour the [[imagery]]
// rasters give the ground and how much of the albedo beneath they replace. Each raster is read per
// band (red, green, blue, or one grey band; an alpha band when it has one) through the same overview
// pyramids, disk cache and tile cache as the elevation sources (raster_pyramid.h, tile_cache.h), at
// the coarsest level whose pixel is no larger than the texel asked for. Rasters are ranked finest
// pixel first, then higher priority, and composited "over" (finest on top) with the weight
//   w = opacity * alpha * coverage * feather(distance inside its border / blend_m),
// the border being only where the raster ends inside the world (a global raster has none).
// Pixels are 8-bit sRGB, decoded to linear albedo.
#include "planet/core/error.h"
#include "planet/sources/imagery_source.h"
#include "planet/sources/raster_file.h"
#include "planet/sources/raster_pyramid.h"
#include "planet/sources/tile_cache.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace globe {

// Linear albedo and the share of the albedo beneath it replaces (straight alpha, [0, 1]).
struct ImageryColour {
  glm::dvec3 albedo{0.0};
  double alpha = 0.0;
};

inline constexpr std::size_t kDefaultImageryRamBudget = std::size_t(256) << 20;  // bytes of tiles in RAM

struct ImageryLayer {
  ImagerySource description;
  std::vector<std::unique_ptr<RasterFile>> bands;  // red, green, blue (or one grey), then alpha if any
  std::vector<std::unique_ptr<RasterPyramid>> tiles;
  bool grey = false, alpha = false;
  double blend_m = 0.0;      // resolved (defaultImageryBlend_m when the file gives none)
  bool wrapsX = false;       // geographic and 360 degrees wide: columns wrap across the antimeridian
  bool worldTop = false;     // its top row reaches the north pole (no feather there)
  bool worldBottom = false;  // its bottom row reaches the south pole

  const RasterFacts& facts() const { return bands.front()->facts(); }
};

// Opens one imagery raster's bands and checks what imagery needs (8-bit bands; 1 or 3 colour bands,
// plus alpha). Errors name the file (the planet file reader adds its field).
Result<ImageryLayer> openImageryLayer(const ImagerySource& source, double radius_m);

class ImageryMosaic {
 public:
  // Opens every raster (one that no longer opens is skipped: the planet file loader validated them).
  ImageryMosaic(const std::vector<ImagerySource>& sources, double radius_m,
                std::size_t ramBudgetBytes = kDefaultImageryRamBudget);

  // The composited colour at a direction for a texel of `texel_m` metres (0: full resolution).
  ImageryColour colourAt(const glm::dvec3& unitDirection, double texel_m) const;

  const std::vector<ImageryLayer>& layers() const { return layers_; }
  TileCache& cache() const { return cache_; }

 private:
  std::vector<ImageryLayer> layers_;  // finest first
  mutable TileCache cache_;
};

}  // namespace globe
