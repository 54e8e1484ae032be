#include "terrain_warnings.h"

#include "commands.h"

namespace globe::cli {

void TerrainWarnings::printNew(const Terrain& terrain) {
  const std::span<const std::string> warnings = terrain.warnings();
  for (; printed_ < warnings.size(); ++printed_) printWarning(warnings[printed_]);
}

}  // namespace globe::cli
