#pragma once
// What a planet file's [[imagery]] table says about one colour raster draped over the terrain
// (docs/imagery.md): where it is, where it lies when the file has no georeferencing, how it ranks
// and how it fades into what lies beneath. Plain data; imagery_mosaic.h reads the raster.
#include "planet/sources/raster_file.h"

#include <optional>
#include <string>

namespace globe {

struct ImagerySource {
  std::string path;  // as resolved: relative paths in a planet file are relative to the file's folder
  // The raster's outer pixel edges in WGS 84 degrees, replacing its own georeferencing (a plain
  // JPEG or PNG, such as NASA's Blue Marble); nullopt: the file's (GeoTIFF, world file, VRT, ...).
  std::optional<GeographicExtent> extent;
  int priority = 0;      // higher wins where the resolutions tie
  double opacity = 1.0;  // [0, 1]: how much of the albedo beneath it replaces
  // Feather width (metres) inside the raster's border over which it fades in; < 0: the default,
  // defaultImageryBlend_m. Borders that are the world's (a global raster's poles and antimeridian)
  // have none.
  double blend_m = -1.0;

  bool operator==(const ImagerySource&) const = default;
};

// The default feather: 8 of the raster's pixels, so a regional image meets the procedural colours
// (or a coarser image) as a gradient, not a seam.
inline double defaultImageryBlend_m(double pixel_m) { return 8.0 * pixel_m; }

// At most this many imagery rasters in one planet (each holds up to four open rasters).
inline constexpr int kMaxImagerySources = 16;

}  // namespace globe
