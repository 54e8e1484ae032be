#pragma once
// Cloud-Optimized GeoTIFF height tiles through GDAL's COG driver: one Float32 raster of metres above
// the planet's radius per tile of the geographic tiling, kCogPixels square (pixel-is-area, samples
// at pixel centres), DEFLATE with the floating-point predictor, internal blocks of kCogBlock and the
// overviews the driver adds, georeferenced in longitude/latitude on a sphere of the planet's radius.
#include "planet/core/error.h"
#include "planet/tiling/bake_plan.h"

#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace globe {

inline constexpr int kCogPixels = 256;
inline constexpr int kCogBlock = 128;

// The unit directions of the tile's pixel centres, row 0 the northernmost, appended to `out`.
void appendCogDirections(const TileId& tile, std::vector<glm::dvec3>& out);

// The GeoTIFF's bytes from kCogPixels^2 heights in appendCogDirections order. Safe to call from
// several threads at once.
// Heights are above the planet's sphere or ellipsoid (`flattening`), at geodetic latitude/longitude.
Result<std::string> encodeCogTile(const TileId& tile, const std::vector<double>& heights_m, double radius_m,
                                  const std::string& planet_name, double flattening = 0.0);

}  // namespace globe
