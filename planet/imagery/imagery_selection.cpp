#include "planet/imagery/imagery_selection.h"

#include "planet/analysis/percentile.h"
#include "planet/geometry/triacontahedron.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace globe {

namespace {
// The level whose nodes measure the face mapping's widest node: deep enough that a node's width
// halves with each level below it (to well under the margin), shallow enough to visit all at start.
constexpr int kWidthSurveyLevel = 4;
// Headroom on the surveyed width for the mapping's variation inside a level-4 node.
constexpr double kWidthMargin = 1.05;
// Fragments blend to the parent's texels over [kBlendStart, 1] x D(L - 1) (terrain_fragment.glsl).
constexpr double kBlendStart = 0.8;

// Largest great-circle edge (radians) of any node at `level`.
double widestEdge_rad(const FaceMapping& mapping, int level) {
  double widest = 0.0;
  const uint32_t side = uint32_t{1} << level;
  for (int face = 0; face < kFaceCount; ++face) {
    for (uint32_t y = 0; y < side; ++y) {
      for (uint32_t x = 0; x < side; ++x) {
        const NodeId node{uint8_t(face), uint8_t(level), x, y};
        for (int e = 0; e < 4; ++e) {
          const glm::dvec3 a = nodeCornerDirection(mapping, node, e),
                           b = nodeCornerDirection(mapping, node, (e + 1) % 4);
          widest = std::max(widest, std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)));
        }
      }
    }
  }
  return widest;
}
}  // namespace

ImagerySelector::ImagerySelector(const ImageryConfig& config, double radius_m, double minElevation_m,
                                 double maxElevation_m, const Ellipsoid& shape, const FaceMapping& mapping)
    : config_(config),
      minRadius_m_(std::max(0.0, radius_m * (1.0 - shape.flattening()) + minElevation_m)),
      maxRadius_m_(radius_m + maxElevation_m),
      shape_(shape),
      mapping_(mapping) {
  assert(config.tileCells > 0 && config.magnification_px > 0.0 && config.maxLevel <= kMaxNodeLevel);
  width0_m_ =
      widestEdge_rad(mapping, kWidthSurveyLevel) * double(1u << kWidthSurveyLevel) * maxRadius_m_ * kWidthMargin;
}

double ImagerySelector::levelWidth_m(int level) const { return std::ldexp(width0_m_, -level); }

double ImagerySelector::adequateFrom_m(int level, double pixelsPerRadian) const {
  return pixelsPerRadian * levelWidth_m(level) / (double(config_.tileCells) * kBlendStart * config_.magnification_px);
}

double ImagerySelector::distanceTo(const NodeBounds& bounds) const {
  return std::max(distanceToBounds(bounds, camera_m_), nearest_m_);
}

RadiusRange ImagerySelector::rangeOf(const NodeId& node, const NodeResidency& geometry) const {
  if (std::optional<RadiusRange> known = geometry.knownRadiusRange(node)) return *known;
  return {minRadius_m_, maxRadius_m_};
}

NodeId ImagerySelector::coarsestAdequate(const NodeId& node, const NodeResidency& geometry) {
  NodeId tile = node;
  while (tile.level > 0) {
    const NodeId parent = tile.parent();
    auto [it, added] = ancestorDistance_.try_emplace(parent.key(), 0.0);
    if (added) it->second = distanceTo(NodeBounds::forNode(mapping_, parent, rangeOf(parent, geometry), shape_));
    if (it->second < adequateFrom_m(parent.level, lambda_)) break;
    tile = parent;
  }
  return tile;
}

void ImagerySelector::wantedTiles(const SelectedNode& node, const NodeResidency& geometry) {
  blocks_.clear();
  const NodeId id = node.id;
  const RadiusRange range = rangeOf(id, geometry);
  const NodeBounds bounds = NodeBounds::forNode(mapping_, id, range, shape_);
  if (id.level >= config_.maxLevel || adequate(bounds, id.level)) {
    NodeId tile = adequate(bounds, id.level) ? coarsestAdequate(id, geometry) : id;
    if (tile.level > config_.maxLevel) tile = tile.ancestor(config_.maxLevel);
    blocks_.push_back({tile, distanceTo(bounds), bounds.diagonal(), 0, 0, kImageryCellsPerSide});
    return;
  }
  descend(id, bounds, range, kImageryCellLevels, 0, 0, kImageryCellsPerSide);
}

void ImagerySelector::descend(const NodeId& tile, const NodeBounds& bounds, const RadiusRange& range, int levelsLeft,
                              int x0, int y0, int size) {
  if (levelsLeft == 0 || tile.level >= config_.maxLevel || adequate(bounds, tile.level)) {
    blocks_.push_back({tile, distanceTo(bounds), bounds.diagonal(), x0, y0, size});
    return;
  }
  // The node's radius range bounds its descendants' too.
  const std::array<RadiusRange, 4> ranges{range, range, range, range};
  const std::array<NodeBounds, 4> children = childBounds(mapping_, tile, bounds, ranges, shape_);
  const int half = size / 2;
  for (int q = 0; q < 4; ++q)
    descend(tile.child(q), children[size_t(q)], range, levelsLeft - 1, x0 + (q & 1) * half, y0 + (q >> 1) * half, half);
}

ImageryCell ImagerySelector::resolve(const NodeId& wanted, double distance_m, NodeResidency& imagery,
                                     ImagerySelection& out) {
  auto [it, added] = resolved_.try_emplace(wanted.key());
  if (!added) return it->second;
  NodeId tile = wanted, below = wanted;
  while (!imagery.isResident(tile) && tile.level > 0) {
    below = tile;
    tile = tile.parent();
  }
  if (!imagery.isResident(tile)) {  // not even the root: nothing to draw yet
    imagery.request(tile, RequestPriority::kRoot, distance_m);
    ++out.stats.requests;
    return it->second = ImageryCell{tile, false};
  }
  if (tile.key() != wanted.key()) {
    // One level at a time towards the wanted tile: the pool keeps its resident set closed under parents.
    imagery.request(below, RequestPriority::kVisible, distance_m);
    ++out.stats.requests;
  }
  if (drawnTiles_.insert(tile.key()).second) {
    SelectedNode drawn;
    drawn.id = tile;
    out.tiles.push_back(drawn);
    out.stats.deepest = std::max<uint32_t>(out.stats.deepest, tile.level);
  }
  return it->second = ImageryCell{tile, true};
}

double ImagerySelector::magnification(const ImageryCell& cell, const Wanted& wanted) const {
  const int level = cell.tile.level;
  const double texel = levelWidth_m(level) / double(config_.tileCells);
  double m = lambda_ * texel / std::max(wanted.distance_m, nearest_m_);
  if (level > 0) {
    // Where the cell reaches the blend band, its fragments show the parent's texels too.
    const double blendFrom = kBlendStart * adequateFrom_m(level - 1, lambda_);
    if (wanted.distance_m + wanted.diagonal_m >= blendFrom)
      m = std::max(m, lambda_ * 2.0 * texel / std::max(wanted.distance_m, blendFrom));
  }
  return m;
}

void ImagerySelector::select(const glm::dvec3& camera_m, double nearest_m, double pixelsPerRadian,
                             std::span<const SelectedNode> nodes, const NodeResidency& geometry, NodeResidency& imagery,
                             ImagerySelection& out) {
  camera_m_ = camera_m;
  nearest_m_ = std::max(nearest_m, 0.0);
  lambda_ = pixelsPerRadian;
  ancestorDistance_.clear();
  resolved_.clear();
  drawnTiles_.clear();
  magnifications_.clear();
  out.cells.assign(nodes.size() * kImageryCellsPerNode, ImageryCell{});
  out.tiles.clear();
  out.stats = ImageryStats{};
  for (size_t k = 0; k < nodes.size(); ++k) {
    wantedTiles(nodes[k], geometry);
    for (const Wanted& w : blocks_) {
      const ImageryCell cell = resolve(w.tile, w.distance_m, imagery, out);
      const double m = cell.resident ? magnification(cell, w) : 0.0;
      // Wanted tiles are adequate unless the table's depth or maxLevel stopped them.
      const bool capped = w.distance_m < adequateFrom_m(w.tile.level, lambda_);
      for (int y = w.y0; y < w.y0 + w.size; ++y)
        for (int x = w.x0; x < w.x0 + w.size; ++x) {
          out.cells[k * kImageryCellsPerNode + size_t(y * kImageryCellsPerSide + x)] = cell;
          out.stats.capped += capped ? 1 : 0;
          if (!cell.resident) continue;
          if (cell.tile.key() != w.tile.key()) ++out.stats.fallbacks;
          magnifications_.push_back(m);
        }
    }
  }
  out.stats.tiles = uint32_t(out.tiles.size());
  summarise(out.stats);
}

void ImagerySelector::summarise(ImageryStats& stats) {
  if (magnifications_.empty()) return;
  std::sort(magnifications_.begin(), magnifications_.end());
  stats.p95Magnification_px = nearestRankPercentile(magnifications_, 95);
  stats.maxMagnification_px = magnifications_.back();
}

ImageryStats ImagerySelector::meshMapStats(const glm::dvec3& camera_m, double nearest_m, double pixelsPerRadian,
                                           std::span<const SelectedNode> nodes, uint32_t mapCells,
                                           const NodeResidency& geometry) {
  camera_m_ = camera_m;
  nearest_m_ = std::max(nearest_m, 0.0);
  lambda_ = pixelsPerRadian;
  magnifications_.clear();
  for (const SelectedNode& n : nodes) {
    const NodeBounds bounds = NodeBounds::forNode(mapping_, n.id, rangeOf(n.id, geometry), shape_);
    const double distance_m = distanceTo(bounds);
    const double texel = levelWidth_m(n.id.level - (n.partial ? 1 : 0)) / double(mapCells);
    double m = lambda_ * texel / distance_m;
    // The parent's map shows from where the morph band may start on (never nearer than its floor).
    const double morphFrom = n.morph.startFloor_m;
    if (!n.partial && n.id.level > 0 && distance_m + bounds.diagonal() >= morphFrom)
      m = std::max(m, lambda_ * 2.0 * texel / std::max(distance_m, morphFrom));
    magnifications_.push_back(m);
  }
  ImageryStats stats;
  summarise(stats);
  return stats;
}

}  // namespace globe
