#include "engine/render/grid_indices.h"

#include <meshoptimizer.h>

namespace globe {

namespace {

// Triangles of an n x n grid (vertex i + j (n+1)), every cell split along (i, j)-(i+1, j+1).
void appendGrid(uint32_t n, std::vector<uint32_t>& out) {
  const uint32_t side = n + 1;
  const size_t first = out.size();
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t v00 = j * side + i, v10 = v00 + 1, v01 = v00 + side, v11 = v01 + 1;
      out.insert(out.end(), {v00, v10, v11, v00, v11, v01});
    }
  }
  // Row-major order re-shades most vertices (a row is longer than a post-transform cache); meshopt
  // reorders the triangles for cache reuse.
  meshopt_optimizeVertexCache(&out[first], &out[first], out.size() - first, size_t(side) * side);
}

// The skirt strip of one node edge (terrain_vertex.glsl): top vertex (n+1)^2 + t is grid vertex t
// along the edge, bottom vertex (n+1)^2 + (n+1) + t its flared copy.
void appendSkirt(uint32_t n, std::vector<uint32_t>& out) {
  const uint32_t top = (n + 1) * (n + 1), bottom = top + n + 1;
  for (uint32_t t = 0; t < n; ++t)
    out.insert(out.end(), {top + t, top + t + 1, bottom + t + 1, top + t, bottom + t + 1, bottom + t});
}

}  // namespace

GridIndexRanges gridIndexRanges(uint32_t gridCells) {
  GridIndexRanges r;
  r.indices.reserve(size_t(6) * (gridCells * gridCells + gridCells * gridCells / 4 + gridCells + gridCells / 2));
  for (uint32_t range = 0; range < 4; ++range) {
    const uint32_t n = range % 2 == 0 ? gridCells : gridCells / 2;
    r.first[range] = uint32_t(r.indices.size());
    if (range < 2)
      appendGrid(n, r.indices);
    else
      appendSkirt(n, r.indices);
    r.count[range] = uint32_t(r.indices.size()) - r.first[range];
  }
  return r;
}

}  // namespace globe
