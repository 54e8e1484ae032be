#pragma once
// The CRS of a planet's own latitude/longitude, for the rasters globe writes and reads back.
#include <string>

namespace globe {

// WKT of (geodetic) longitude/latitude on the planet's sphere of `radius_m` (inverse flattening 0), or
// on its ellipsoid of equatorial radius `radius_m` and `flattening`: the CRS of baked COG tiles
// (engine/bake/cog_tile.cpp) and of the quantized-mesh raster read back (bake.json keeps no
// flattening, so a tileset read back is labelled a sphere; its heights are the same either way).
std::string planetCrsWkt(double radius_m, const std::string& planetName, double flattening = 0.0);

}  // namespace globe
