#pragma once
// The terrain's degradations (Terrain::warnings: frame budget reached, pool exhausted, generation
// failed), handed out once each as they happen, so every command and the viewer report each one
// once ("globe: warning: ..." on stderr; the viewer also on screen).
#include "engine/render/terrain.h"

#include <cstddef>
#include <span>
#include <string>

namespace globe {

class TerrainWarnings {
 public:
  // The warnings `terrain` raised since the last call.
  std::span<const std::string> takeNew(const Terrain& terrain);
  // The next call hands out every warning of a (new) terrain again: after the viewer's reload.
  void reset() { taken_ = 0; }

 private:
  std::size_t taken_ = 0;
};

}  // namespace globe
