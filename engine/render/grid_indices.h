#pragma once
// The index buffer every terrain node is drawn with (terrain_vertex.glsl numbers the vertices): four
// ranges, the full grid, the half grid (a partial node's), the full skirt strip and the half one.
#include <array>
#include <cstdint>
#include <vector>

namespace globe {

struct GridIndexRanges {
  std::vector<uint32_t> indices;
  std::array<uint32_t, 4> first{};  // of each range, in indices
  std::array<uint32_t, 4> count{};
};

// `gridCells`: cells per node side (a power of two, >= 2). Grids are ordered for the post-transform
// vertex cache (meshoptimizer).
GridIndexRanges gridIndexRanges(uint32_t gridCells);

}  // namespace globe
