#pragma once
// The terrain's degradations (Terrain::warnings: frame budget reached, pool exhausted, generation
// failed) printed once each, as they happen, as "globe: warning: ..." on stderr.
#include "engine/render/terrain.h"

#include <cstddef>

namespace globe::cli {

class TerrainWarnings {
 public:
  // Prints the warnings `terrain` raised since the last call.
  void printNew(const Terrain& terrain);

 private:
  size_t printed_ = 0;
};

}  // namespace globe::cli
