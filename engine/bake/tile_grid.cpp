#include "engine/bake/tile_grid.h"

#include "planet/camera/camera.h"

namespace globe {

void appendGridDirections(const TileId& tile, int cells, std::vector<glm::dvec3>& out) {
  for (int j = -1; j <= cells + 1; ++j) {
    for (int i = -1; i <= cells + 1; ++i) {
      const LonLat p = tileSampleLonLat(tile, cells, i, j);
      out.push_back(directionFromLatLon(p.lat_deg, p.lon_deg));
    }
  }
}

}  // namespace globe
