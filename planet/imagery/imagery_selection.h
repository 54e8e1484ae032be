#pragma once
// Imagery LOD separate from geometry [Rodrigues 2016, §3.2]: the surface textures (normal, colour) live in tiles
// of their own quadtree over the 30 faces — a tile has the id of the node with the same square, and
// T x T map cells — refined by texel magnification instead of the mesh's screen error. Each drawn
// node is covered by an 8 x 8 table of cells three levels below it; a cell shows the tile over it
// (an ancestor, the node itself, or a descendant), so imagery can be up to three levels finer than
// the mesh, or any number of levels coarser.
//
// The rule, a CDLOD for textures [Strugar 2009]: a level-L tile is fine enough from the distance
// D(L) = lambda * W(L) / (T * 0.8 * m) on, where W(L) bounds the width of every level-L node
// (metres), lambda is pixels per radian and m the most screen pixels a texel may cover. The tile
// drawn is the coarsest one whose bounds lie at least D(L) away. Its fragments blend towards the
// parent's texels (which each tile holds over its quadrant) over [0.8, 1] * D(L - 1): a parent's texel
// then covers at most m pixels, and where a tile meets its coarser neighbour (at least D(L - 1) away,
// or that neighbour would not have been chosen) it shows exactly the neighbour's texels — no seams.
//
// Tiles come from a NodeResidency of their own (the imagery pool): a cell whose tile is not resident
// shows the nearest resident ancestor and asks for the next level towards it, as the mesh does.
#include "planet/geometry/ellipsoid.h"
#include "planet/geometry/face_mapping.h"
#include "planet/geometry/node_bounds.h"
#include "planet/lod/node_residency.h"
#include "planet/lod/selection.h"

#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace globe {

// Cells per side of a drawn node's imagery table, and how many levels below the node they lie.
inline constexpr int kImageryCellLevels = 3;
inline constexpr int kImageryCellsPerSide = 1 << kImageryCellLevels;
inline constexpr int kImageryCellsPerNode = kImageryCellsPerSide * kImageryCellsPerSide;

struct ImageryConfig {
  uint32_t tileCells = 128;       // T: map cells per tile side
  double magnification_px = 1.5;  // m: the most screen pixels one texel may cover; > 0
  int maxLevel = 26;              // deepest tile level, <= kMaxNodeLevel
};

// One cell of a drawn node's table.
struct ImageryCell {
  NodeId tile;            // the tile drawn over the cell (valid when resident)
  bool resident = false;  // false: no tile yet, not even a root (the vertex colour is drawn)
};

struct ImageryStats {
  uint32_t tiles = 0;      // distinct tiles drawn
  uint32_t requests = 0;   // tiles asked of the imagery pool this frame
  uint32_t fallbacks = 0;  // cells drawing a coarser tile than wanted (its tile is being made)
  uint32_t capped = 0;     // cells wanting a tile deeper than their table (kImageryCellLevels) or maxLevel
  uint32_t deepest = 0;    // deepest level drawn
  // Upper bound of the screen pixels one drawn texel covers (lambda * texel width / distance, the
  // blend towards the parent included), over all cells: the largest, and the 95th percentile.
  double maxMagnification_px = 0.0;
  double p95Magnification_px = 0.0;
};

struct ImagerySelection {
  std::vector<ImageryCell> cells;   // kImageryCellsPerNode per drawn node, in the nodes' order, rows along v
  std::vector<SelectedNode> tiles;  // the distinct tiles drawn (to pin them in the imagery pool)
  ImageryStats stats;
};

class ImagerySelector {
 public:
  // `radius_m`, `maxElevation_m`: the planet's (the widths W(L) are bounded at the highest ground).
  ImagerySelector(const ImageryConfig& config, double radius_m, double minElevation_m, double maxElevation_m,
                  const Ellipsoid& shape = Ellipsoid(), const FaceMapping& mapping = RhombusFaceMapping::get());

  // Metres from which a level-L tile is fine enough (D(L)) at `pixelsPerRadian`.
  double adequateFrom_m(int level, double pixelsPerRadian) const;
  // The last select()'s pixels per radian.
  double pixelsPerRadian() const { return lambda_; }
  // W(L): no level-L node is wider (metres, any edge, at the highest ground).
  double levelWidth_m(int level) const;
  const ImageryConfig& config() const { return config_; }

  // Tiles for every drawn node. `nearest_m`: no surface point is nearer the camera than this (its
  // height above the ground below it; distances to bounds are floored there, since at low altitude
  // the camera lies inside the bounds' radius range). `geometry` gives nodes' known radius ranges.
  void select(const glm::dvec3& camera_m, double nearest_m, double pixelsPerRadian, std::span<const SelectedNode> nodes,
              const NodeResidency& geometry, NodeResidency& imagery, ImagerySelection& out);
  // The same bound for maps tied to the mesh, to compare: each drawn node's own map of `mapCells`
  // cells a side (a partial node draws its parent's), blended to the parent's in its morph band.
  // Fills the magnification fields only.
  ImageryStats meshMapStats(const glm::dvec3& camera_m, double nearest_m, double pixelsPerRadian,
                            std::span<const SelectedNode> nodes, uint32_t mapCells, const NodeResidency& geometry);

 private:
  // The wanted tile of a square block of a node's cells.
  struct Wanted {
    NodeId tile;
    double distance_m;  // from the camera to the smallest bounds computed around the block
    double diagonal_m;  // those bounds' diagonal
    int x0, y0, size;   // the block: cells [x0, x0 + size) x [y0, y0 + size) of the table
  };
  // blocks_ = the wanted tiles covering `node`'s table.
  void wantedTiles(const SelectedNode& node, const NodeResidency& geometry);
  // Splits `tile`'s block (its table cells from (x0, y0), size a side) until its quarters are
  // adequate or cells; the node's radius range bounds them all.
  void descend(const NodeId& tile, const NodeBounds& bounds, const RadiusRange& range, int levelsLeft, int x0, int y0,
               int size);
  // The coarsest adequate ancestor-or-self of `node`, whose own bounds are adequate.
  NodeId coarsestAdequate(const NodeId& node, const NodeResidency& geometry);
  double distanceTo(const NodeBounds& bounds) const;
  bool adequate(const NodeBounds& bounds, int level) const {
    return distanceTo(bounds) >= adequateFrom_m(level, lambda_);
  }
  RadiusRange rangeOf(const NodeId& node, const NodeResidency& geometry) const;
  // The drawn tile for a wanted one: itself when resident, else the nearest resident ancestor (the
  // next level towards the wanted tile is requested).
  ImageryCell resolve(const NodeId& wanted, double distance_m, NodeResidency& imagery, ImagerySelection& out);
  double magnification(const ImageryCell& cell, const Wanted& wanted) const;
  // Sorts magnifications_ and writes their largest and 95th percentile.
  void summarise(ImageryStats& stats);

  ImageryConfig config_;
  double minRadius_m_, maxRadius_m_;
  Ellipsoid shape_;
  const FaceMapping& mapping_;
  double width0_m_ = 0.0;  // W(0)
  // Per select(): camera, floor, lambda; ancestors' distances; wanted tile -> drawn cell.
  glm::dvec3 camera_m_{0.0};
  double nearest_m_ = 0.0;
  double lambda_ = 0.0;
  std::unordered_map<uint64_t, double> ancestorDistance_;
  std::unordered_map<uint64_t, ImageryCell> resolved_;
  std::unordered_set<uint64_t> drawnTiles_;
  std::vector<double> magnifications_;
  std::vector<Wanted> blocks_;  // wantedTiles()'s
};

}  // namespace globe
