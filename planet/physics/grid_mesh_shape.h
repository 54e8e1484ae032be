#pragma once
// A collision mesh as Bullet sees it: the node's (cells + 1)^2 vertex grid in the node's tangent
// frame (z up), indexed by its grid instead of a BVH. In that frame a level-14 node's grid is an
// affine lattice in x, y to within a few hundredths of a cell (the face mapping's curvature across
// 250 m and the radial elevation's tilt away from the centre's up), so a query box maps to a range of
// cells through the lattice's inverse, widened by the largest deviation of any vertex (measured when
// the shape is made, so the range never misses a triangle, whatever the level). Blocks of cells
// carry their height range, so a body in the air above the ground touches no triangle.
//
// Bullet's BVH (btBvhTriangleMeshShape) took ~1.3 ms of CPU to build per arriving mesh on the
// stepping thread and a tree walk per body-mesh pair and step (a fifth of a step with 1 000
// bodies); the grid needs neither. Private to planet/physics (it includes Bullet).
#include <BulletCollision/CollisionShapes/btConcaveShape.h>

#include <cstdint>
#include <vector>

namespace globe {

class GridMeshShape final : public btConcaveShape {
 public:
  // `local_m`: xyz per vertex in the tangent frame, row j = v index, (cells + 1)^2 vertices; the
  // triangles are collisionGridIndices(cells)' (planet/physics/collision_mesh.h), same numbering.
  GridMeshShape(uint32_t cells, std::vector<double> local_m);

  // Every triangle whose bounding box overlaps [aabbMin, aabbMax] (local metres), part 0.
  void processAllTriangles(btTriangleCallback* callback, const btVector3& aabbMin,
                           const btVector3& aabbMax) const override;
  void getAabb(const btTransform& t, btVector3& aabbMin, btVector3& aabbMax) const override;
  // Scaling is not supported (the meshes are metres): only (1, 1, 1) is kept.
  void setLocalScaling(const btVector3& scaling) override;
  const btVector3& getLocalScaling() const override { return scaling_; }
  void calculateLocalInertia(btScalar mass, btVector3& inertia) const override;  // static: zero
  const char* getName() const override { return "GridMesh"; }

  const btVector3& localMin() const { return localMin_; }
  const btVector3& localMax() const { return localMax_; }
  uint32_t cells() const { return cells_; }
  // Largest distance (cells) of a vertex from its place in the affine lattice, along i and j.
  double deviationI() const { return deviation_[0]; }
  double deviationJ() const { return deviation_[1]; }

 private:
  btVector3 vertex(uint32_t i, uint32_t j) const;
  // Cells [i0, i1] x [j0, j1] whose triangles may overlap the box in x, y; false when none.
  bool cellRange(const btVector3& aabbMin, const btVector3& aabbMax, int range[4]) const;
  void measureLattice();
  void measureBlocks();

  uint32_t cells_;
  std::vector<double> local_m_;
  btVector3 localMin_, localMax_;
  btVector3 scaling_{1, 1, 1};
  // Lattice: xy = origin + i * axisI + j * axisJ; inverse_ maps xy - origin to (i, j).
  double origin_[2] = {0, 0};
  double inverse_[4] = {0, 0, 0, 0};   // row-major 2 x 2
  double deviation_[2] = {0, 0};       // cells
  bool affine_ = false;                // false: degenerate lattice, every query takes every cell
  uint32_t blocks_ = 1;                // per side
  std::vector<double> blockHeight_m_;  // min z, max z per block, row-major
};

}  // namespace globe
