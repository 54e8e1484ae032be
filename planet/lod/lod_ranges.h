#pragma once
// CDLOD view ranges [Strugar 2009; Frasson 2018, §3.3.1] and morph constants, computed in one place.
//
// refineRange(d): a node at depth d is subdivided when its bounds meet the ball of this radius around
// the camera. Nominal: baseRange * ratio^(maxDepth - 1 - d) * distanceMultiplier. They then grow so
// that R(d) >= (R(d+1) + D(d+1)) * (1 + 1e-9) + 1 mm for every d, D(k) being the largest bounds
// diagonal observed at depth k: this is what makes the selection a restricted quadtree (edge
// neighbours differ by at most one level) even over tall terrain — a node at depth d+2 is only
// selected within R(d+1) + D(d+1) of the camera, and a depth-d node only beyond R(d).
//
// Tolerance-driven ranges (tolerance_px > 0) replace the nominal ranges by the screen-space error
// rule [Cozzi 2011, §12.1]: a node is refined while rho = lambda * E / d > tolerance,
// lambda = pixels per radian of the view, d = distance to the node's bounds, E = the error of drawing
// depth d instead of d+1. Per depth, E(d) is the largest geometric error observed in payloads of
// depth d+1 (a depth-(d+1) payload's morph deviation is the error its parent's resolution makes
// there), extrapolated by 1 / rangeRatio per level from the deepest observed level until depth d+1
// has been seen. Nominal R(d) = lambda * E(d) / tolerance; the growth rule below still applies, so
// the selection stays restricted and the morph bands stay per level (crack-free across seams).
//
// Roughness (tolerance mode with a RoughnessMap, docs/lod.md "Roughness"): from depth
// RoughnessMap::firstDepth() on, the range is a field over the sphere instead of one number,
// R_d(x) = max(lambda * min(K(d) * w_d(x), E(d)) / tolerance, growth), with w_d the map's relative
// roughness and K(d) = max over observed payloads of E / max_node w_d: the map's error scale, which
// every payload seen stays below. So a plain is refined only as far as its own error needs, and no
// place further than with one range per depth. Stored at the map's grid points, bilinear between
// them; the growth rule holds point by point with the field's slope S:
// R_d(g) >= (R_{d+1}(g) + D(d+1) * (1 + S_{d+1})) * (1 + 1e-9) + 1 mm, which keeps the quadtree
// restricted; a node is refined when its bounds meet the ball of its largest R_d, and its morph band
// ends at R_{d-1} interpolated per vertex, so neighbours agree on every shared vertex.
//
// A node drawn at depth d (full) lives between R(d) and R(d-1) and morphs towards its parent's
// resolution over the last `morphFraction` of that band: morphEnd = R(d-1), morphStart = morphEnd -
// morphFraction * (R(d-1) - R(d)). Depth 0 never morphs (start = end = +infinity).
#include <array>
#include <memory>
#include <vector>

#include "planet/core/error.h"
#include "planet/geometry/node_id.h"
#include "planet/lod/roughness_map.h"

namespace globe {

struct LodRangeConfig {
  int maxDepth = 20;                // deepest level selected (0 .. kMaxNodeLevel)
  double baseRange_m = 0.0;         // R(maxDepth - 1) before the multiplier; 0 = auto (see below)
  double rangeRatio = 2.0;          // R(d) / R(d+1) before growth; >= 1
  double distanceMultiplier = 1.0;  // scales every range: > 1 = finer detail farther away
  double morphFraction = 0.5;       // (0, 1]: last part of each band that morphs (source: half)
  // > 0: ranges from the payloads' geometric error so the screen error stays within this many pixels
  // (distanceMultiplier and baseRange_m are then unused); 0: distance ranges.
  double tolerance_px = 0.0;
  // Tolerance mode: ranges also follow where the relief is rough (a RoughnessMap the terrain builds
  // from its planet, LodRanges::setRoughness); false: one range per depth. Off by default: on
  // earthlike it buys no triangles at equal screen error (docs/tradeoffs.md).
  bool roughness = false;
  // Tolerance mode with surface textures (payload_layout.h): a node of depth d is also refined while
  // its texels would cover more than texel_px pixels, R(d) >= lambda * W(d) / (texelsPerNode *
  // texel_px), W the nominal node width: the per-pixel detail then reaches the screen where the
  // geometric error alone would keep plains and sea coarse. 0: geometric error only.
  double texel_px = 0.0;
  uint32_t texelsPerNode = 0;  // the surface texture's texels per node side (grid cells x map scale)
};

// Pixels per radian of a view `height_px` tall with vertical field of view `verticalFov_rad`:
// lambda = height / (2 tan(fov / 2)) (seed 000's w / (2 tan(fov / 2)) with the vertical pair).
double pixelsPerRadian(double height_px, double verticalFov_rad);

// Auto base range: this many max-depth node widths (nominal edge arc length). Chosen with the
// selection benchmark (docs/lod.md): ~6 gives ~1000 selected nodes for a ground camera with a 90°
// frustum at depth 20, and a 128-cell node's samples ~1–4 px apart on a 1920-px, 60° view.
inline constexpr double kAutoBaseRangeInNodeWidths = 6.0;

struct MorphRange {
  double start_m = 0.0;  // distance where k leaves 0
  double end_m = 0.0;    // distance where k reaches 1 (the parent's resolution)
};

// k in [0, 1] for a vertex at distance_m; 0 when the range does not morph (infinite start).
double morphFactor(const MorphRange& morph, double distance_m);

// The morph band of one drawn node, which may vary over it (roughness): the end is bilinear between
// its corners' values, the start follows the band rule from it. Uniform bands have four equal ends.
struct NodeMorph {
  std::array<double, 4> end_m{};  // at the node's corners (u0 v0, u1 v0, u0 v1, u1 v1); +inf: never
  double ownRange_m = 0.0;        // refine range of the drawn depth over the node (0 at max depth)
  double startFloor_m = 0.0;      // the band starts no nearer (unmorphed where a finer neighbour may be)
  double fraction = 0.5;          // morphFraction
  // The band at (s, t) in [0, 1]^2 of the node's (u, v) square.
  MorphRange at(double s, double t) const;
};

// Nominal width of a node at `depth` (metres): the rhombus edge arc on a sphere of radius_m / 2^depth.
double nominalNodeWidth(int depth, double radius_m);
// "cm per sample": nominal sample spacing (metres) of a node grid of gridCells cells at `depth`.
// Depth 20, 128 cells, R = 6371 km gives ≈ 0.031 m (the source's "≈ 3 cm").
double metresPerSample(int depth, int gridCells, double radius_m);

class LodRanges {
 public:
  // radius_m: planet radius (> 0, finite), used by the auto base range. Bad values are an Error.
  static Result<LodRanges> create(const LodRangeConfig& config, double radius_m);

  int maxDepth() const { return config_.maxDepth; }
  const LodRangeConfig& config() const { return config_; }
  // R(d) (metres) for d in [0, maxDepth); +infinity is never returned.
  double refineRange(int depth) const { return range_[static_cast<size_t>(depth)]; }
  // Morph band of a node drawn at the resolution of `depth` (a partial node at depth d uses d - 1).
  // With roughness: the widest band of that depth (NodeMorph for one node).
  MorphRange morph(int depth) const { return morph_[static_cast<size_t>(depth)]; }

  // Tolerance mode: let the ranges follow where the terrain is rough (nullptr: per depth only).
  void setRoughness(std::shared_ptr<const RoughnessMap> map);
  const RoughnessMap* roughness() const { return map_.get(); }
  // The range a node is refined within: the largest R over it (refineRange(depth) without roughness).
  double refineRangeOver(const NodeId& node) const;
  // The band of a selected node (partial: drawn at its parent's depth, over its own square).
  NodeMorph morphFor(const NodeId& node, bool partial) const;
  // Recomputes the range fields if an observation changed them (the selection calls it per pass).
  void refresh();

  // Record a node's bounds diagonal (metres); returns true when a range grew (callers that need the
  // restriction guarantee for this frame re-run their selection).
  bool observeDiagonal(int depth, double diagonal_m) {
    if (diagonal_m <= maxDiagonal_[static_cast<size_t>(depth)]) return false;
    maxDiagonal_[static_cast<size_t>(depth)] = diagonal_m;
    return recompute();
  }
  double maxDiagonal(int depth) const { return maxDiagonal_[static_cast<size_t>(depth)]; }

  bool toleranceDriven() const { return config_.tolerance_px > 0.0; }
  // Tolerance mode: record a payload's geometric error (metres) at its depth; true when a range
  // changed (re-select, as for observeDiagonal). Errors only grow, so ranges never shrink once
  // their depth has been seen: no popping from the statistics.
  bool observeError(int depth, double error_m);
  // The same for a payload node: with roughness its error is divided by max_node w (the K above).
  bool observeError(const NodeId& node, double error_m);
  // Tolerance mode: the view's pixels per radian (pixelsPerRadian()); true when a range changed.
  bool setPixelsPerRadian(double lambda);
  // E(d) the tolerance ranges use (metres; 0 before any payload is known).
  double estimatedError(int depth) const;
  // Forget observed diagonals (e.g. after switching planets).
  void resetObservedDiagonals();

  // Everything the ranges learned from payloads (observeDiagonal, observeError): with the
  // configuration, their whole state. Ranges only grow, so they depend on every node seen before;
  // a resumed movie restores what an uninterrupted run had learned by then (issue 40 item 9).
  struct Observations {
    std::array<double, kMaxNodeLevel + 1> maxDiagonal{};
    std::array<double, kMaxNodeLevel + 1> maxError{};
    std::array<double, kMaxNodeLevel + 1> maxCalibrated{};
    bool operator==(const Observations&) const = default;
  };
  Observations observations() const { return {maxDiagonal_, maxError_, maxCalibrated_}; }
  void restore(const Observations& o);

 private:
  bool recompute();  // true when any range changed (with roughness: marks the fields for refresh())
  void recomputeBands();
  LodRangeConfig config_;
  std::array<double, kMaxNodeLevel + 1> nominal_{};
  std::array<double, kMaxNodeLevel + 1> texelRadians_{};  // W(d) / (texelsPerNode * texel_px) / radius: 0 without
  std::array<double, kMaxNodeLevel + 1> range_{};
  std::array<double, kMaxNodeLevel + 1> maxDiagonal_{};
  std::array<double, kMaxNodeLevel + 1> maxError_{};       // per payload depth; < 0: none observed
  std::array<double, kMaxNodeLevel + 1> maxCalibrated_{};  // K: max error / max_node w, likewise
  double pixelsPerRadian_ = 0.0;
  std::array<MorphRange, kMaxNodeLevel + 1> morph_{};  // per drawn depth, derived from range_
  // Roughness: the map, and per depth with a field the range at each grid point and its slope.
  bool fieldDepth(int depth) const {
    return map_ && toleranceDriven() && depth >= RoughnessMap::firstDepth() && depth < config_.maxDepth;
  }
  void recomputeFields();
  std::shared_ptr<const RoughnessMap> map_;
  std::vector<std::vector<double>> field_;              // [depth][point], metres
  std::array<double, kMaxNodeLevel + 1> fieldSlope_{};  // per metre
  bool dirty_ = false;
};

}  // namespace globe
