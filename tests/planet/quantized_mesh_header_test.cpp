// A quantized-mesh tile whose header heights are not finite (issue 40: a baked tile saying
// maxHeight = inf made bounds of infinite size and a physics step that never ended) is refused by
// the decoder, where the heights enter, like any other corrupt tile.
#include "planet/tiling/quantized_mesh_decoder.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

namespace globe {
namespace {

// A header (centre, min/max height, bounding sphere, horizon point) and no vertices, triangles or edges.
std::string emptyTile(float minHeight, float maxHeight) {
  std::string bytes(88 + 4 + 4 + 4 * 4, '\0');
  std::memcpy(&bytes[24], &minHeight, 4);
  std::memcpy(&bytes[28], &maxHeight, 4);
  return bytes;
}

TEST(QuantizedMeshHeader, NonFiniteOrHugeHeightsAreRefused) {
  const float inf = std::numeric_limits<float>::infinity();
  for (auto [lo, hi] : {std::pair{0.0f, inf}, {-inf, 0.0f}, {0.0f, 3.4e38f}, {100.0f, 0.0f}}) {
    std::string why;
    EXPECT_FALSE(decodeQuantizedMesh(emptyTile(lo, hi), &why).has_value()) << lo << " " << hi;
    EXPECT_EQ(why, "header heights are not finite, beyond 1000 km or out of order");
  }
  std::string why;
  (void)decodeQuantizedMesh(emptyTile(-10.0f, 8000.0f), &why);
  EXPECT_NE(why, "header heights are not finite, beyond 1000 km or out of order");
}

}  // namespace
}  // namespace globe
