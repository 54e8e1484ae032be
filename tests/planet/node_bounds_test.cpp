#include "planet/geometry/node_bounds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "tests/support/lod_test_util.h"

namespace globe {
namespace {

using testing::kEarthRadius_m;

constexpr RadiusRange kRange{kEarthRadius_m - 11000.0, kEarthRadius_m + 9000.0};

// Surface grid points of `node` (n x n) at radius r.
std::vector<glm::dvec3> gridPoints(const NodeId& node, int n, double r) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  std::vector<glm::dvec3> out;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double u = node.uMin() + node.size() * i / (n - 1);
      const double v = node.vMin() + node.size() * j / (n - 1);
      out.push_back(m.unitPoint(node.face, std::min(u, 1.0), std::min(v, 1.0)) * r);
    }
  }
  return out;
}

// Paths down the quadtree: random, hugging a seam (x = 0 or y = 0), and into each face corner.
std::vector<std::vector<NodeId>> testPaths(int depth) {
  std::vector<std::vector<NodeId>> paths;
  std::mt19937_64 rng(21);
  for (int f = 0; f < kFaceCount; ++f) {
    for (int kind = 0; kind < 7; ++kind) {
      std::vector<NodeId> path{{static_cast<uint8_t>(f), 0, 0, 0}};
      for (int d = 0; d < depth; ++d) {
        int q = static_cast<int>(rng() % 4);
        if (kind < 4) q = kind;          // into corner `kind`
        if (kind == 4) q &= 2;           // along u = 0 (a seam)
        if (kind == 5) q = (q & 1) | 2;  // along v = 1 (a seam)
        path.push_back(path.back().child(q));
      }
      paths.push_back(path);
    }
  }
  return paths;
}

TEST(NodeBounds, ChildGridPointsInsideParentDownToDepth24) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  int checked = 0;
  for (const auto& path : testPaths(24)) {
    for (size_t i = 0; i + 1 < path.size(); ++i) {
      const NodeBounds parent = NodeBounds::forNode(m, path[i], kRange);
      // Both ways of building a child: from its id, and from the parent (what selection does).
      const std::array<RadiusRange, 4> ranges = {kRange, kRange, kRange, kRange};
      const std::array<NodeBounds, 4> fromParent = childBounds(m, path[i], parent, ranges);
      for (int q = 0; q < 4; ++q) {
        const NodeId child = path[i].child(q);
        const NodeBounds own = NodeBounds::forNode(m, child, kRange);
        for (double r : {kRange.min_m, kRange.max_m}) {
          for (const glm::dvec3& p : gridPoints(child, 5, r)) {
            ASSERT_TRUE(parent.contains(p, 1e-6)) << "level " << int(child.level) << " face " << int(child.face);
            ASSERT_TRUE(own.contains(p, 1e-6));
            ASSERT_TRUE(fromParent[static_cast<size_t>(q)].contains(p, 1e-6));
            ++checked;
          }
        }
        for (int c = 0; c < 8; ++c) {
          EXPECT_NEAR(glm::length(own.corners[static_cast<size_t>(c)] -
                                  fromParent[static_cast<size_t>(q)].corners[static_cast<size_t>(c)]),
                      0.0, 1e-6);
        }
      }
    }
  }
  EXPECT_GT(checked, 100000);
}

TEST(NodeBounds, PlanesOutwardCornersInsideSphereHolds) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  std::mt19937_64 rng(4);
  for (int i = 0; i < 500; ++i) {
    const int level = static_cast<int>(rng() % 25);
    const NodeId id = testing::randomNodeAt(rng, level);
    const NodeBounds b = NodeBounds::forNode(m, id, kRange);
    const double tol = 1e-6;
    for (const glm::dvec3& c : b.corners) {
      EXPECT_TRUE(b.contains(c, tol));
      EXPECT_LE(glm::length(c - b.sphereCentre), b.sphereRadius);
    }
    // The centre of the patch at mid radius is strictly inside; far above and below are not.
    const glm::dvec3 mid = b.centreDirection * (0.5 * (kRange.min_m + kRange.max_m));
    EXPECT_TRUE(b.contains(mid));
    EXPECT_FALSE(b.contains(b.centreDirection * (kRange.max_m + 1.0)));
    if (level >= 4) {  // big nodes dip far below S_min: their bottom plane is at S_min * cos(corner)
      EXPECT_FALSE(b.contains(b.centreDirection * (kRange.min_m * 0.9)));
    }
    EXPECT_FALSE(b.contains(-mid));
    EXPECT_GE(b.diagonal(), glm::length(b.corners[0] - b.corners[6]));
  }
}

TEST(NodeBounds, TightenShrinksAndStillContains) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  for (int level : {0, 5, 12, 20, 24}) {
    const NodeId id{17, static_cast<uint8_t>(level), 0, (1u << level) - 1};  // at a seam corner
    NodeBounds b = NodeBounds::forNode(m, id, kRange);
    const double before = b.diagonal();
    const RadiusRange real{kEarthRadius_m - 3.0, kEarthRadius_m + 2.0};
    b.tighten(real);
    EXPECT_LE(b.diagonal(), before);
    EXPECT_EQ(b.radius.min_m, real.min_m);
    for (double r : {real.min_m, real.max_m}) {
      for (const glm::dvec3& p : gridPoints(id, 7, r)) EXPECT_TRUE(b.contains(p, 1e-6));
    }
    EXPECT_FALSE(b.contains(b.centreDirection * (real.max_m + 0.5)));
  }
}

// Frank–Wolfe on the convex hull of the 8 corners: an upper bound on the squared distance and the
// duality gap (true squared distance >= value - gap).
std::pair<double, double> hullDistanceSquared(const NodeBounds& b, const glm::dvec3& p) {
  glm::dvec3 x = b.corners[0];
  double gap = 0.0;
  for (int it = 0; it < 3000; ++it) {
    const glm::dvec3 g = 2.0 * (x - p);
    size_t best = 0;
    for (size_t i = 1; i < 8; ++i) {
      if (glm::dot(g, b.corners[i]) < glm::dot(g, b.corners[best])) best = i;
    }
    const glm::dvec3 d = b.corners[best] - x;
    gap = -glm::dot(g, d);
    const double dd = glm::dot(d, d);
    if (dd == 0.0 || gap <= 0.0) break;
    const double step = std::clamp(gap / (2.0 * dd), 0.0, 1.0);
    x += step * d;
  }
  return {glm::dot(x - p, x - p), std::max(gap, 0.0)};
}

TEST(NodeBounds, SphereIntersectionMatchesHullDistance) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int hits = 0;
  int misses = 0;
  for (int i = 0; i < 3000; ++i) {
    const int level = static_cast<int>(rng() % 16);
    const NodeId id = testing::randomNodeAt(rng, level);
    const NodeBounds b = NodeBounds::forNode(m, id, kRange);
    // A point near the node: its centre plus an offset of a few node sizes in a random direction.
    const glm::dvec3 p = b.sphereCentre + testing::randomDirection(rng) * (b.sphereRadius * 3.0 * unit(rng));
    const double distance = distanceToBounds(b, p);
    const auto [fw, gap] = hullDistanceSquared(b, p);
    const double scale = b.sphereRadius;
    EXPECT_LE(distance * distance, fw + 1e-9 * scale * scale);
    EXPECT_GE(distance * distance, fw - gap - 1e-9 * scale * scale);
    for (double factor : {0.999, 1.001}) {
      const double r = distance * factor + (factor > 1 ? 1e-9 * scale : 0.0);
      const bool expected = factor > 1.0;
      if (distance == 0.0 && !expected) continue;
      EXPECT_EQ(intersectsSphere(b, p, r), expected) << "distance " << distance;
      (expected ? hits : misses)++;
    }
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(misses, 500);
}

}  // namespace
}  // namespace globe
