// The grid-indexed collision shape (planet/physics/grid_mesh_shape.h) reports every triangle that
// meets a query box (the only ones that can touch what the box holds) and none whose own bounding
// box misses it, each once with its corners; Bullet's BVH reported those whose bounding boxes
// overlap, a superset of the first and equal to the second set: for payload grids
// at the collision level and at a coarse level (where the lattice bends most), at a pole, a face
// seam and a polyhedron vertex, in planet-aligned axes (a tilted grid) and warped by hand.
#include "planet/physics/grid_mesh_shape.h"
#include "planet/geometry/face_mapping.h"
#include "planet/model/planet_file.h"
#include "planet/physics/collision_mesh.h"
#include "planet/physics/drop_sites.h"

#include <LinearMath/btAabbUtil2.h>
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <set>
#include <string_view>

namespace globe {
namespace {

struct Collect final : btTriangleCallback {
  std::set<int> triangles;
  std::map<int, std::array<btVector3, 3>> corners;
  void processTriangle(btVector3* triangle, int partId, int triangleIndex) override {
    EXPECT_EQ(partId, 0);
    EXPECT_TRUE(triangles.insert(triangleIndex).second) << "triangle " << triangleIndex << " reported twice";
    corners[triangleIndex] = {triangle[0], triangle[1], triangle[2]};
  }
};

// Every query box: random centres over and around the grid's bounds, sizes from a fraction of a
// cell to several cells, in every height band.
void expectTrianglesOfBox(uint32_t cells, const std::vector<double>& vertices_m, std::string_view what) {
  const GridMeshShape shape(cells, vertices_m);
  const std::vector<int> indices = collisionGridIndices(cells);
  auto vertex = [&](int v) { return btVector3(vertices_m[3 * v], vertices_m[3 * v + 1], vertices_m[3 * v + 2]); };
  const btVector3 extent = shape.localMax() - shape.localMin();
  std::mt19937_64 rng(cells);
  std::uniform_real_distribution<double> unit(-0.1, 1.1), size(0.002, 0.2);
  for (int q = 0; q < 300; ++q) {
    btVector3 centre, half;
    for (int axis = 0; axis < 3; ++axis) {
      centre[axis] = shape.localMin()[axis] + unit(rng) * extent[axis];
      half[axis] = size(rng) * std::max(extent.x(), extent.y());
    }
    const btVector3 low = centre - half, high = centre + half;
    Collect collect;
    shape.processAllTriangles(&collect, low, high);
    for (int t = 0; 3 * t < int(indices.size()); ++t) {
      btVector3 triangle[3] = {vertex(indices[3 * t]), vertex(indices[3 * t + 1]), vertex(indices[3 * t + 2])};
      const bool reported = collect.triangles.count(t) != 0;
      if (!TestTriangleAgainstAabb2(triangle, low, high)) {
        ASSERT_FALSE(reported) << what << ", query " << q << ": triangle " << t << " is nowhere near the box";
        continue;
      }
      if (reported) continue;
      // Not reported: then no point of it is in the box (a dense barycentric grid of points).
      constexpr int kSteps = 24;
      for (int a = 0; a <= kSteps; ++a)
        for (int b = 0; a + b <= kSteps; ++b) {
          const btVector3 p =
              (double(a) * triangle[0] + double(b) * triangle[1] + double(kSteps - a - b) * triangle[2]) /
              double(kSteps);
          const bool inside = p.x() >= low.x() && p.x() <= high.x() && p.y() >= low.y() && p.y() <= high.y() &&
                              p.z() >= low.z() && p.z() <= high.z();
          ASSERT_FALSE(inside) << what << ", query " << q << ": triangle " << t << " meets the box, not reported";
        }
    }
    for (const auto& [t, c] : collect.corners)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(c[size_t(k)], vertex(indices[size_t(3 * t + k)])) << what << ", triangle " << t;
  }
}

const ElevationModel& testModel() {
  static const ElevationModel model(*loadPlanetFile(GLOBE_SOURCE_DIR "/assets/planets/earthlike.toml"));
  return model;
}

TEST(GridMeshShape, ReportsEveryTriangleMeetingTheBox) {
  const auto& mapping = RhombusFaceMapping::get();
  CpuCollisionMeshSource source(testModel(), 16);
  int tested = 0;
  for (const DropSite& site : specialDropSites()) {
    if (tested++ % 7 != 0) continue;  // a pole, vertices, seams, ±180° (every seventh site)
    for (int level : {14, 6}) {
      const CollisionMesh mesh = source.generateNow(nodeAt(mapping.locate(site.direction), level));
      expectTrianglesOfBox(mesh.cells, mesh.vertices_m, dropSiteKindName(site.kind));
    }
  }
}

TEST(GridMeshShape, WarpedAndDegenerateGridsMissNothing) {
  constexpr uint32_t kCells = 16;
  std::vector<double> warped, flat;
  for (uint32_t j = 0; j <= kCells; ++j)
    for (uint32_t i = 0; i <= kCells; ++i) {
      const double x = double(i) + 0.3 * double(j) + 0.8 * std::sin(0.7 * double(j));  // sheared, bent rows
      const double y = double(j) + 0.6 * std::cos(0.5 * double(i));
      warped.insert(warped.end(), {x, y, 3.0 * std::sin(0.4 * x) * std::cos(0.3 * y)});
      flat.insert(flat.end(), {double(i), 0.0, double(j)});  // a vertical wall: no x-y lattice
    }
  expectTrianglesOfBox(kCells, warped, "warped");
  expectTrianglesOfBox(kCells, flat, "degenerate");
  EXPECT_GT(GridMeshShape(kCells, warped).deviationI(), 0.5);
}

}  // namespace
}  // namespace globe
