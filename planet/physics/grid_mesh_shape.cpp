#include "planet/physics/grid_mesh_shape.h"

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionShapes/btTriangleCallback.h>
#include <LinearMath/btAabbUtil2.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace globe {

namespace {

constexpr uint32_t kBlockCells = 4;     // cells per block side (a block's height range)
constexpr double kLatticeSlack = 1e-6;  // cells, for the rounding of the lattice's inverse

}  // namespace

GridMeshShape::GridMeshShape(uint32_t cells, std::vector<double> local_m)
    : cells_(cells), local_m_(std::move(local_m)) {
  assert(cells_ >= 1 && local_m_.size() == 3 * size_t(cells_ + 1) * size_t(cells_ + 1));
  // An unused concave type: Bullet treats CUSTOM_CONCAVE_SHAPE_TYPE as its SDF shape, and gives
  // TRIANGLE_MESH_SHAPE_PROXYTYPE its BVH paths; every other concave type takes the generic
  // processAllTriangles paths (contacts, ray and convex casts).
  m_shapeType = FAST_CONCAVE_MESH_PROXYTYPE;
  localMin_ = btVector3(BT_LARGE_FLOAT, BT_LARGE_FLOAT, BT_LARGE_FLOAT);
  localMax_ = -localMin_;
  for (size_t k = 0; k + 2 < local_m_.size(); k += 3) {
    const btVector3 v(local_m_[k], local_m_[k + 1], local_m_[k + 2]);
    localMin_.setMin(v);
    localMax_.setMax(v);
  }
  measureLattice();
  measureBlocks();
}

btVector3 GridMeshShape::vertex(uint32_t i, uint32_t j) const {
  const size_t k = 3 * (size_t(j) * (cells_ + 1) + i);
  return {local_m_[k], local_m_[k + 1], local_m_[k + 2]};
}

// The lattice through the corners (0, 0), (cells, 0), (0, cells), and how far any vertex is from it.
void GridMeshShape::measureLattice() {
  const btVector3 o = vertex(0, 0);
  const btVector3 a = (vertex(cells_, 0) - o) / double(cells_);
  const btVector3 b = (vertex(0, cells_) - o) / double(cells_);
  const double det = a.x() * b.y() - a.y() * b.x();
  affine_ =
      std::isfinite(det) && std::abs(det) > 1e-12 * (a.x() * a.x() + a.y() * a.y() + b.x() * b.x() + b.y() * b.y());
  if (!affine_) return;
  origin_[0] = o.x(), origin_[1] = o.y();
  inverse_[0] = b.y() / det, inverse_[1] = -b.x() / det;
  inverse_[2] = -a.y() / det, inverse_[3] = a.x() / det;
  for (uint32_t j = 0; j <= cells_; ++j)
    for (uint32_t i = 0; i <= cells_; ++i) {
      const btVector3 v = vertex(i, j);
      const double dx = v.x() - origin_[0], dy = v.y() - origin_[1];
      deviation_[0] = std::max(deviation_[0], std::abs(inverse_[0] * dx + inverse_[1] * dy - double(i)));
      deviation_[1] = std::max(deviation_[1], std::abs(inverse_[2] * dx + inverse_[3] * dy - double(j)));
    }
  deviation_[0] += kLatticeSlack;
  deviation_[1] += kLatticeSlack;
  affine_ = std::isfinite(deviation_[0]) && std::isfinite(deviation_[1]);
}

// Height range of each block's vertices (its cells' corners, borders included).
void GridMeshShape::measureBlocks() {
  blocks_ = (cells_ + kBlockCells - 1) / kBlockCells;
  blockHeight_m_.assign(2 * size_t(blocks_) * blocks_, 0.0);
  for (uint32_t bj = 0; bj < blocks_; ++bj)
    for (uint32_t bi = 0; bi < blocks_; ++bi) {
      double low = std::numeric_limits<double>::infinity(), high = -low;
      for (uint32_t j = bj * kBlockCells; j <= std::min(cells_, (bj + 1) * kBlockCells); ++j)
        for (uint32_t i = bi * kBlockCells; i <= std::min(cells_, (bi + 1) * kBlockCells); ++i) {
          const double z = local_m_[3 * (size_t(j) * (cells_ + 1) + i) + 2];
          low = std::min(low, z);
          high = std::max(high, z);
        }
      blockHeight_m_[2 * (size_t(bj) * blocks_ + bi)] = low;
      blockHeight_m_[2 * (size_t(bj) * blocks_ + bi) + 1] = high;
    }
}

// A point of a cell's triangles is a convex combination of its corners, whose lattice coordinates
// are within the deviation of (i .. i + 1, j .. j + 1); the box's image in lattice coordinates is
// the parallelogram of its four corners' images. The two overlap only for the cells returned.
bool GridMeshShape::cellRange(const btVector3& aabbMin, const btVector3& aabbMax, int range[4]) const {
  const int last = int(cells_) - 1;
  if (!affine_) {
    range[0] = range[2] = 0;
    range[1] = range[3] = last;
    return true;
  }
  double low[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double high[2] = {-low[0], -low[1]};
  for (int c = 0; c < 4; ++c) {
    const double dx = ((c & 1) ? aabbMax.x() : aabbMin.x()) - origin_[0];
    const double dy = ((c & 2) ? aabbMax.y() : aabbMin.y()) - origin_[1];
    for (int axis = 0; axis < 2; ++axis) {
      const double u = inverse_[2 * axis] * dx + inverse_[2 * axis + 1] * dy;
      low[axis] = std::min(low[axis], u);
      high[axis] = std::max(high[axis], u);
    }
  }
  for (int axis = 0; axis < 2; ++axis) {
    const double from = std::ceil(low[axis] - 1.0 - deviation_[axis]);
    const double to = std::floor(high[axis] + deviation_[axis]);
    if (!(from <= double(last) && to >= 0.0)) return false;  // also NaN
    range[2 * axis] = int(std::max(from, 0.0));
    range[2 * axis + 1] = int(std::min(to, double(last)));
  }
  return true;
}

void GridMeshShape::processAllTriangles(btTriangleCallback* callback, const btVector3& aabbMin,
                                        const btVector3& aabbMax) const {
  int range[4];
  if (aabbMin.z() > localMax_.z() || aabbMax.z() < localMin_.z() || !cellRange(aabbMin, aabbMax, range)) return;
  for (uint32_t bj = uint32_t(range[2]) / kBlockCells; bj <= uint32_t(range[3]) / kBlockCells; ++bj)
    for (uint32_t bi = uint32_t(range[0]) / kBlockCells; bi <= uint32_t(range[1]) / kBlockCells; ++bi) {
      const double* height = &blockHeight_m_[2 * (size_t(bj) * blocks_ + bi)];
      if (aabbMin.z() > height[1] || aabbMax.z() < height[0]) continue;
      const uint32_t j0 = std::max(uint32_t(range[2]), bj * kBlockCells);
      const uint32_t j1 = std::min(uint32_t(range[3]), bj * kBlockCells + kBlockCells - 1);
      const uint32_t i0 = std::max(uint32_t(range[0]), bi * kBlockCells);
      const uint32_t i1 = std::min(uint32_t(range[1]), bi * kBlockCells + kBlockCells - 1);
      for (uint32_t j = j0; j <= j1; ++j)
        for (uint32_t i = i0; i <= i1; ++i) {
          const btVector3 p00 = vertex(i, j), p10 = vertex(i + 1, j);
          const btVector3 p01 = vertex(i, j + 1), p11 = vertex(i + 1, j + 1);
          // collisionGridIndices' split: (00, 10, 11) and (00, 11, 01), triangles 2 k and 2 k + 1.
          btVector3 first[3] = {p00, p10, p11};
          btVector3 second[3] = {p00, p11, p01};
          const int cell = int(j * cells_ + i);
          if (TestTriangleAgainstAabb2(first, aabbMin, aabbMax)) callback->processTriangle(first, 0, 2 * cell);
          if (TestTriangleAgainstAabb2(second, aabbMin, aabbMax)) callback->processTriangle(second, 0, 2 * cell + 1);
        }
    }
}

void GridMeshShape::getAabb(const btTransform& t, btVector3& aabbMin, btVector3& aabbMax) const {
  btTransformAabb(localMin_, localMax_, getMargin(), t, aabbMin, aabbMax);
}

void GridMeshShape::setLocalScaling(const btVector3& scaling) {
  assert(scaling == btVector3(1, 1, 1) && "GridMeshShape does not scale");
  (void)scaling;
}

void GridMeshShape::calculateLocalInertia(btScalar /*mass*/, btVector3& inertia) const { inertia.setValue(0, 0, 0); }

}  // namespace globe
