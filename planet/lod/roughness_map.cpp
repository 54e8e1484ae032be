#include "planet/lod/roughness_map.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "planet/geometry/triacontahedron.h"

namespace globe {
namespace {

constexpr int kSide = RoughnessMap::kCells + 1;  // grid points per face side
constexpr double kInverseCells = 1.0 / RoughnessMap::kCells;
// A bilinear cell's gradient from its edge slopes: |grad| <= (|g_u| + |g_v|) / sin(angle between
// the edges); the rhombus cells meet at >= 63.4 degrees (sin >= 0.894), with a margin for the
// sphere's distortion of a cell and for arcs against chords.
constexpr double kCellGradientFactor = 2.5;
constexpr float kSmallestRelative = 1.0e-4F;  // keeps w > 0 (LodRanges divides by it)

double slopeBound(const std::vector<RoughnessMap::PointPair>& pairs, std::span<const float> table) {
  double worst = 0.0;
  for (const RoughnessMap::PointPair& p : pairs)
    worst = std::max(worst, std::abs(double(table[p.a]) - double(table[p.b])) * p.inverseGap);
  return worst * kCellGradientFactor;
}

struct DirectionKey {
  std::size_t operator()(const glm::dvec3& d) const {
    const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
    return static_cast<std::size_t>(bits(d.x + 0.0) * 0x9e3779b97f4a7c15ULL ^ bits(d.y + 0.0) * 0xc2b2ae3d27d4eb4fULL ^
                                    bits(d.z + 0.0) * 0x165667b19e3779f9ULL);
  }
};

}  // namespace

RoughnessMap RoughnessMap::build(int maxDepth, double minRadius_m, const Model& model, const FaceMapping& mapping) {
  RoughnessMap map;
  map.maxDepth_ = maxDepth;
  map.minRadius_m_ = minRadius_m;
  // The face mapping gives a seam point the same bits from both faces, so equal directions are one point.
  std::unordered_map<glm::dvec3, std::uint32_t, DirectionKey> ids;
  map.index_.resize(static_cast<std::size_t>(kFaceCount) * kSide * kSide);
  for (int f = 0; f < kFaceCount; ++f) {
    for (int j = 0; j < kSide; ++j) {
      for (int i = 0; i < kSide; ++i) {
        const glm::dvec3 d = mapping.unitPoint(f, i * kInverseCells, j * kInverseCells);
        const auto [it, added] = ids.try_emplace(d, static_cast<std::uint32_t>(map.directions_.size()));
        if (added) map.directions_.push_back(d);
        map.index_[(static_cast<std::size_t>(f) * kSide + static_cast<std::size_t>(j)) * kSide +
                   static_cast<std::size_t>(i)] = it->second;
      }
    }
  }
  const std::vector<PointPair> pairs = map.cellPairs();
  const std::size_t depths = static_cast<std::size_t>(maxDepth) + 1;
  std::vector<double> values(map.directions_.size() * depths);
  for (std::size_t p = 0; p < map.directions_.size(); ++p) model(map.directions_[p], {&values[p * depths], depths});
  map.relative_.assign(depths, std::vector<float>(map.directions_.size()));
  map.slope_.assign(depths, 0.0);
  for (std::size_t d = 0; d < depths; ++d) {
    double largest = 0.0;
    for (std::size_t p = 0; p < map.directions_.size(); ++p) largest = std::max(largest, values[p * depths + d]);
    for (std::size_t p = 0; p < map.directions_.size(); ++p) {
      const float r = largest > 0.0 ? static_cast<float>(values[p * depths + d] / largest) : 1.0F;
      map.relative_[d][p] = std::clamp(r, kSmallestRelative, 1.0F);
    }
    map.slope_[d] = slopeBound(pairs, map.relative_[d]);
  }
  return map;
}

std::vector<RoughnessMap::PointPair> RoughnessMap::cellPairs() const {
  std::vector<PointPair> pairs;
  for (int f = 0; f < kFaceCount; ++f) {
    for (int cj = 0; cj < kCells; ++cj) {
      for (int ci = 0; ci < kCells; ++ci) {
        const std::array<std::uint32_t, 4> p{point(f, ci, cj), point(f, ci + 1, cj), point(f, ci, cj + 1),
                                             point(f, ci + 1, cj + 1)};
        for (const auto& [a, b] : {std::pair{0, 1}, {0, 2}, {1, 3}, {2, 3}, {0, 3}, {1, 2}}) {
          const double gap = glm::length(directions_[p[a]] - directions_[p[b]]) * minRadius_m_;
          pairs.push_back({p[a], p[b], 1.0 / gap});
        }
      }
    }
  }
  return pairs;
}

template <class T>
double RoughnessMap::interpolate(std::span<const T> table, int face, double u, double v) const {
  const double x = u * kCells;
  const double y = v * kCells;
  const int ci = std::clamp(static_cast<int>(x), 0, kCells - 1);
  const int cj = std::clamp(static_cast<int>(y), 0, kCells - 1);
  const double s = x - ci;
  const double t = y - cj;
  const double p00 = table[point(face, ci, cj)];
  const double p10 = table[point(face, ci + 1, cj)];
  const double p01 = table[point(face, ci, cj + 1)];
  const double p11 = table[point(face, ci + 1, cj + 1)];
  return (p00 * (1.0 - s) + p10 * s) * (1.0 - t) + (p01 * (1.0 - s) + p11 * s) * t;
}

template <class T>
std::array<double, 4> RoughnessMap::corners(std::span<const T> table, const NodeId& node) const {
  const double u0 = node.uMin(), v0 = node.vMin(), u1 = u0 + node.size(), v1 = v0 + node.size();
  return {interpolate(table, node.face, u0, v0), interpolate(table, node.face, u1, v0),
          interpolate(table, node.face, u0, v1), interpolate(table, node.face, u1, v1)};
}

template <class T>
double RoughnessMap::maxOver(std::span<const T> table, const NodeId& node) const {
  assert(node.level >= firstDepth());
  if (node.level >= kGridLevel) {
    const std::array<double, 4> c = corners(table, node);
    return std::max(std::max(c[0], c[1]), std::max(c[2], c[3]));
  }
  const int step = 1 << (kGridLevel - node.level);
  const int i0 = static_cast<int>(node.x) * step;
  const int j0 = static_cast<int>(node.y) * step;
  double best = 0.0;
  for (int j = j0; j <= j0 + step; ++j) {
    for (int i = i0; i <= i0 + step; ++i) best = std::max(best, static_cast<double>(table[point(node.face, i, j)]));
  }
  return best;
}

template double RoughnessMap::interpolate(std::span<const float>, int, double, double) const;
template double RoughnessMap::interpolate(std::span<const double>, int, double, double) const;
template double RoughnessMap::maxOver(std::span<const float>, const NodeId&) const;
template double RoughnessMap::maxOver(std::span<const double>, const NodeId&) const;
template std::array<double, 4> RoughnessMap::corners(std::span<const float>, const NodeId&) const;
template std::array<double, 4> RoughnessMap::corners(std::span<const double>, const NodeId&) const;

}  // namespace globe
