#pragma once
// The terrain's degradations (Terrain::warnings: frame budget reached, pool exhausted, generation
// failed), handed out once each as they happen, so every command and the viewer report each one
// once ("globe: warning: ..." on stderr; the viewer also on screen).
#include "engine/render/terrain.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace globe {

// A terrain warning with what the user can do in the options `globe` takes (render, bench, movie,
// view share them): the pools' budgets are --vram-mib and --imagery-mib, the frame budget
// --max-nodes and --max-triangles; the node table has no option, so the remedy is less detail.
std::string inOptionTerms(std::string warning);

class TerrainWarnings {
 public:
  // The warnings `terrain` raised since the last call, in the terms of the options a person sets
  // (inOptionTerms).
  std::vector<std::string> takeNew(const Terrain& terrain);
  // The next call hands out every warning of a (new) terrain again: after the viewer's reload.
  void reset() { taken_ = 0; }

 private:
  std::size_t taken_ = 0;
};

}  // namespace globe
