#pragma once
// One vector layer read (vector_features.h) and indexed (vector_index.h) once per process and shared
// by everything that needs it: the planet file's check, the overlay that paints it
// (vector_overlay.h) and `globe planet check`'s description. A layer is known by its whole table
// (VectorLayer) and its file's size and modification time, so an edited file is read again.
#include "planet/core/error.h"
#include "planet/vectors/vector_index.h"
#include "planet/vectors/vector_layer.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace globe {

// What the layer holds, as read and reprojected (for `globe planet check`).
struct VectorLayerFacts {
  std::string layer_name;  // the OGR layer read
  std::size_t features = 0, rings = 0, lines = 0, points = 0, vertices = 0;
  double lat_min_deg = 0.0, lat_max_deg = 0.0, lon_min_deg = 0.0, lon_max_deg = 0.0;  // when vertices > 0
};

struct IndexedVectorLayer {
  VectorLayer style;
  VectorIndex index;
  std::vector<std::int32_t> colour;  // per feature: index into table, -1 = the style's own colours
  std::vector<glm::vec3> table;      // style.colours' values, in map order
  bool has_rings = false, has_lines = false, has_points = false;
  VectorLayerFacts facts;
};

// The layer, read and indexed, or the reason it cannot be (an Error naming the file and the key at
// fault, as readVectorFeatures). Layers that opened stay shared while used; the last few opened are
// kept a while after (at most kMaxVectorLayers, and 5 M vertices together), so the overlay finds
// what the planet file's check read. Thread-safe.
Result<std::shared_ptr<const IndexedVectorLayer>> openIndexedVectorLayer(const VectorLayer& style);

}  // namespace globe
