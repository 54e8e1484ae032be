#pragma once
// One vector layer read from its file, every geometry reprojected to WGS84 latitude/longitude degrees
// and flattened into plain arrays: polygon rings, line strings and points. Multi-geometries and
// collections are flattened, curves linearised. The file is read by the reader a program installs
// (installVectorReader; planet/gdal/gdal_readers.h installs OGR's), so that the domain links no
// file-format library of its own; the overlay (vector_overlay.h) indexes the arrays.
#include "planet/core/error.h"
#include "planet/vectors/vector_layer.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace globe {

// Limits against hostile files, checked while reading (docs/reliability.md).
struct VectorLimits {
  std::size_t max_vertices = 5'000'000;  // per layer
  std::size_t max_features = 1'000'000;  // per layer
};

enum class VectorPartKind : std::uint8_t {
  kRing,   // a polygon ring (outer or inner: even-odd per feature), closed implicitly
  kLine,   // a line string, at least one vertex
  kPoint,  // one vertex
};

struct VectorPart {
  VectorPartKind kind = VectorPartKind::kPoint;
  std::uint32_t feature = 0;  // index into VectorFeatures::features
  std::uint32_t first = 0;    // first vertex
  std::uint32_t count = 0;    // vertices; a ring's closing vertex (equal to the first) is not repeated
};

struct VectorFeature {
  std::int64_t fid = 0;  // OGR's feature id, for messages
  // The index in VectorLayer::colours (map order) of the feature's colour_by value; -1 when the
  // layer has no colour_by or the value is not in the table.
  std::int32_t colour = -1;
};

struct VectorFeatures {
  std::string layer_name;                // the layer read, for messages
  std::vector<double> lat_deg, lon_deg;  // every vertex; lon in [-540, 540], unwrapped along each part
  std::vector<VectorPart> parts;         // in feature order
  std::vector<VectorFeature> features;   // in the layer's order
};

// Reads `layer.path`'s layer `layer.layer` (the first when empty). An Error's file is the path and
// its field the VectorLayer key at fault ("path", "layer" or "colour_by"); its message names the
// layer and, for a bad feature, its FID. Never throws; a truncated or garbage file is an Error.
using VectorReader = Result<VectorFeatures> (*)(const VectorLayer& layer, const VectorLimits& limits);
// Installs the reader readVectorFeatures calls (thread-safe; the last one installed wins).
void installVectorReader(VectorReader reader);
Result<VectorFeatures> readVectorFeatures(const VectorLayer& layer, const VectorLimits& limits = {});

}  // namespace globe
