#pragma once
// Where the terrain is rough, per LOD depth: a relative roughness w_d in (0, 1] stored at the points
// of one fixed grid over the 30 faces (level kGridLevel of the quadtree, 65 km cells on Earth),
// bilinear in (u, v) inside each grid cell. Points on face seams are stored once, so both faces of a
// seam interpolate the same values. LodRanges scales its tolerance-driven ranges by it per point
// (docs/lod.md, "Roughness"), which needs three properties of the field, all kept here:
//   - a node at depth >= kGridLevel lies in one cell, so the field is bilinear over it: its maximum is
//     at its corners and the vertex shader interpolates it exactly from the four corner values;
//   - a node at depth kGridLevel - 1 covers 2 x 2 cells: its maximum is at its 9 grid points;
//   - |w(x) - w(y)| <= slope * |x - y| (metres, at any radius >= minRadius_m): how fast a range
//     may change between neighbouring nodes (the restriction argument). The slope is the largest
//     difference between grid neighbours (edges and diagonals of every cell) per metre at
//     minRadius_m, times the factor that bounds a bilinear cell's gradient by its edge slopes.
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "planet/geometry/face_mapping.h"
#include "planet/geometry/node_id.h"

namespace globe {

class RoughnessMap {
 public:
  static constexpr int kGridLevel = 6;
  static constexpr int kCells = 1 << kGridLevel;  // cells per face side
  // Unnormalised roughness (>= 0, finite) at a unit direction for every depth 0..maxDepth.
  using Model = std::function<void(const glm::dvec3& direction, std::span<double> perDepth)>;

  // Evaluates `model` at every grid point (what it misses between points, LodRanges' calibration
  // against the payloads' errors makes up for), then each depth is divided by
  // its largest value. minRadius_m: the lowest terrain radius (metres), for the slopes.
  static RoughnessMap build(int maxDepth, double minRadius_m, const Model& model,
                            const FaceMapping& mapping = RhombusFaceMapping::get());

  int maxDepth() const { return maxDepth_; }
  // Depths the map describes; coarser depths use plain per-depth ranges.
  static constexpr int firstDepth() { return kGridLevel - 1; }
  std::size_t pointCount() const { return directions_.size(); }
  const glm::dvec3& direction(std::size_t point) const { return directions_[point]; }
  std::uint32_t point(int face, int i, int j) const {
    return index_[(static_cast<std::size_t>(face) * (kCells + 1) + static_cast<std::size_t>(j)) * (kCells + 1) +
                  static_cast<std::size_t>(i)];
  }
  // w_d per point, in (0, 1].
  std::span<const float> relative(int depth) const { return relative_[static_cast<std::size_t>(depth)]; }
  // Bound on |w_d(x) - w_d(y)| / |x - y|, per metre.
  double slope(int depth) const { return slope_[static_cast<std::size_t>(depth)]; }

  // Per-point tables (w, or LodRanges' ranges): the bilinear value at (u, v) of `face`; the largest
  // value over a node of depth >= firstDepth(); the values at its corners (u0 v0, u1 v0, u0 v1, u1 v1).
  template <class T>
  double interpolate(std::span<const T> table, int face, double u, double v) const;
  template <class T>
  double maxOver(std::span<const T> table, const NodeId& node) const;
  template <class T>
  std::array<double, 4> corners(std::span<const T> table, const NodeId& node) const;
  // Every cell's edges and diagonals: the two points and 1 / their distance at minRadius_m.
  struct PointPair {
    std::uint32_t a, b;
    double inverseGap;  // per metre
  };

 private:
  std::vector<PointPair> cellPairs() const;
  int maxDepth_ = 0;
  double minRadius_m_ = 0.0;
  std::vector<std::uint32_t> index_;          // (face, j, i) -> point
  std::vector<glm::dvec3> directions_;        // per point
  std::vector<std::vector<float>> relative_;  // [depth][point]
  std::vector<double> slope_;                 // [depth]
};

}  // namespace globe
