#pragma once
// The spatial index of one vector layer (vector_overlay.h's query side), so that a query costs the
// same however many vertices the layer has: a pyramid of latitude/longitude grids, the finest sized
// from the data, each coarser level holding the geometry simplified to 1/8 of its cell. A cell
// lists the edges and points that cross it; a row lists where its centre line crosses polygon
// rings and which features are inside between crossings, so even-odd insideness is one binary
// search plus the crossings inside one cell. Longitudes wrap: cells are taken modulo 360 degrees.
#include "planet/core/error.h"
#include "planet/vectors/vector_features.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace globe {

// What one feature has near a query point; distances in metres on the sphere (local tangent plane).
struct FeatureProximity {
  std::uint32_t feature = 0;
  double ring_m = std::numeric_limits<double>::infinity();   // its nearest polygon edge
  double line_m = std::numeric_limits<double>::infinity();   // its nearest line string
  double point_m = std::numeric_limits<double>::infinity();  // its nearest point
  std::uint8_t row_copies = 0;  // internal: even-odd per longitude copy (vector_index.cpp, classify)
  std::uint8_t cell_copies = 0;
  bool inside() const { return (row_copies ^ cell_copies) != 0; }
};

// One thread's working space for queries: grown once, then no allocation per query.
struct ProximityScratch {
  std::vector<FeatureProximity> found;  // near's answer, in feature order
  std::vector<std::uint32_t> slot;      // feature -> index in found, valid where stamp == generation
  std::vector<std::uint32_t> stamp;
  std::uint32_t generation = 0;
};

// Open addressing from a 64-bit key to its rank among the keys given to build.
class KeyTable {
 public:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  void build(std::span<const std::uint64_t> keys);
  std::uint32_t find(std::uint64_t key) const;

 private:
  static constexpr std::uint64_t kEmpty = std::numeric_limits<std::uint64_t>::max();  // never a key
  std::uint64_t hash(std::uint64_t key) const { return (key * 0x9E3779B97F4A7C15ull) >> shift_; }
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> values_;
  std::uint64_t mask_ = 0;
  int shift_ = 63;
};

// A layer's geometry at one level of detail; rings repeat their first vertex at the end.
struct IndexVertex {
  double lat_deg = 0.0, lon_deg = 0.0;
};
struct IndexGeometry {
  std::vector<IndexVertex> vertices;  // interleaved: a query reads both coordinates of a vertex
  std::vector<VectorPart> parts;
};

// An edge (or a point) listed in a cell: its first vertex, and feature << 3 | kind << 1 | has_next.
struct CellEntry {
  std::uint32_t vertex = 0;
  std::uint32_t tag = 0;
};

struct IndexLevel {
  double cell_deg = 0.0;
  std::int64_t rows = 0, cols = 0;
  double tolerance_deg = 0.0;             // of the simplification
  std::size_t geometry = 0;               // index into VectorIndex's geometries
  KeyTable cells;                         // row * cols + col -> cell rank
  std::vector<std::uint32_t> cell_start;  // entries of cell i: [cell_start[i], cell_start[i + 1])
  std::vector<CellEntry> entries;
  KeyTable rows_table;                    // row -> row rank
  std::vector<std::uint32_t> row_start;   // crossings of row i: [row_start[i], row_start[i + 1])
  std::vector<double> crossing_lon_deg;   // sorted within a row
  std::vector<std::uint32_t> span_start;  // features inside after crossing j: [span_start[j], span_start[j + 1])
  std::vector<std::uint32_t> span_features;
  KeyTable occupied;  // cells holding exact geometry (simplified levels only: mayTouch never misses a part)
};

class VectorIndex {
 public:
  // Errors when the layer's polygons overlap so much that the rows' inside lists pass a memory
  // budget (the message names no file: the caller adds it). The index is in degrees: the same one
  // serves any sphere, which each query names by its metres per degree of arc.
  static Result<VectorIndex> build(const VectorFeatures& features);

  // Fills scratch.found, in feature order, with every feature having a part within `radius_m` of
  // the point or a polygon containing it. Geometry may be simplified by up to `accuracy_m`.
  void near(double metres_per_degree, double lat_deg, double lon_deg, double accuracy_m, double radius_m,
            ProximityScratch& scratch) const;

  // False when no part lies within `grow_m` of the box and no polygon contains it (conservative:
  // true may mean "near"). Longitudes in degrees, any range; the box may cross the antimeridian.
  bool mayTouch(double metres_per_degree, double latMin_deg, double latMax_deg, double lonMin_deg, double lonMax_deg,
                double grow_m, ProximityScratch& scratch) const;

  std::size_t featureCount() const { return feature_count_; }
  bool empty() const { return geometries_.empty() || geometries_[0].parts.empty(); }

 private:
  struct Box {
    double lat0 = 0.0, lat1 = 0.0, lon0 = 0.0, lon1 = 0.0;
  };
  struct Window {
    std::int64_t row0 = 0, row1 = 0, col0 = 0, colCount = 0;
  };
  std::size_t chooseLevel(double lat_deg, double accuracy_deg, double radius_deg) const;
  Window window(const IndexLevel& level, double lat_deg, double lon_deg, double radius_deg) const;
  void measure(const IndexLevel& level, const Window& w, double metres_per_degree, double lat_deg, double lon_deg,
               double radius_m, ProximityScratch& scratch) const;
  void measureCell(const IndexLevel& level, std::uint32_t cell, double lat_deg, double lon_deg, double radius_m,
                   double xScale, double yScale, ProximityScratch& scratch) const;
  void classify(const IndexLevel& level, double lat_deg, double lon_deg, ProximityScratch& scratch) const;
  bool cellTouches(const IndexLevel& level, std::int64_t row, std::int64_t col, const Box& box,
                   std::size_t& budget) const;
  FeatureProximity& slot(std::uint32_t feature, ProximityScratch& scratch) const;

  std::vector<IndexGeometry> geometries_;  // [0] exact, then simplified
  std::vector<IndexLevel> levels_;         // finest first; cell_deg doubles per level
  std::size_t feature_count_ = 0;
};

}  // namespace globe
