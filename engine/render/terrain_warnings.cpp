#include "engine/render/terrain_warnings.h"

namespace globe {

std::span<const std::string> TerrainWarnings::takeNew(const Terrain& terrain) {
  const std::span<const std::string> all = terrain.warnings();
  const std::size_t first = taken_ < all.size() ? taken_ : all.size();
  taken_ = all.size();
  return all.subspan(first);
}

}  // namespace globe
