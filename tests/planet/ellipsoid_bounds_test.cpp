// Node bounds and horizon culling on ellipsoids (WGS84 and an extreme flattening of 0.1): every
// terrain point p(n) + h n of a node lies inside its six planes, children's inside their parent's,
// to depth 24 on random, seam-hugging and vertex-hugging paths; the planes stay close to the
// surface they bound; horizon culling never drops a visible node for cameras 0 m and 1 m above the
// equator, the poles and mid-latitudes.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include <glm/geometric.hpp>

#include "planet/geometry/node_bounds.h"
#include "planet/lod/horizon_cone.h"
#include "tests/support/lod_test_util.h"

namespace globe {
namespace {

struct Shape {
  const char* name;
  double flattening;
};
const Shape kShapes[] = {{"WGS84", 1.0 / 298.257223563}, {"Flattening0p1", 0.1}};
constexpr double kA_m = 6378137.0;
constexpr double kMinHeight_m = -11000.0;
constexpr double kMaxHeight_m = 9000.0;

Ellipsoid shapeOf(const Shape& s) { return Ellipsoid::create(kA_m, s.flattening).value(); }

// Terrain points of `node` on an n x n grid of geodetic normals at each height.
std::vector<glm::dvec3> terrainPoints(const Ellipsoid& e, const NodeId& node, int n, std::initializer_list<double> h) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  std::vector<glm::dvec3> out;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double u = std::min(node.uMin() + node.size() * i / (n - 1), 1.0);
      const double v = std::min(node.vMin() + node.size() * j / (n - 1), 1.0);
      for (double height : h) out.push_back(e.position(m.unitPoint(node.face, u, v), height));
    }
  }
  return out;
}

RadiusRange rangeOf(const std::vector<glm::dvec3>& points) {
  RadiusRange r{1e300, 0.0};
  for (const glm::dvec3& p : points) {
    r.min_m = std::min(r.min_m, glm::length(p));
    r.max_m = std::max(r.max_m, glm::length(p));
  }
  return r;
}

// The planet-wide range the selection starts from (LodSelector's default).
RadiusRange planetRange(const Ellipsoid& e) {
  return {e.polarRadius_m() + kMinHeight_m, e.equatorialRadius_m() + kMaxHeight_m};
}

std::vector<std::vector<NodeId>> testPaths(int depth) {
  std::vector<std::vector<NodeId>> paths;
  std::mt19937_64 rng(21);
  for (int f = 0; f < kFaceCount; f += 2) {
    for (int kind = 0; kind < 7; ++kind) {
      std::vector<NodeId> path{{static_cast<uint8_t>(f), 0, 0, 0}};
      for (int d = 0; d < depth; ++d) {
        int q = static_cast<int>(rng() % 4);
        if (kind < 4) q = kind;          // into corner `kind` (the 12 five-fold and 20 three-fold vertices)
        if (kind == 4) q &= 2;           // along u = 0 (a seam)
        if (kind == 5) q = (q & 1) | 2;  // along v = 1 (a seam)
        path.push_back(path.back().child(q));
      }
      paths.push_back(path);
    }
  }
  return paths;
}

class EllipsoidBounds : public ::testing::TestWithParam<Shape> {};
INSTANTIATE_TEST_SUITE_P(Shapes, EllipsoidBounds, ::testing::ValuesIn(kShapes),
                         [](const ::testing::TestParamInfo<Shape>& p) { return std::string(p.param.name); });

TEST_P(EllipsoidBounds, TerrainPointsInsideOwnAndParentBoundsDownToDepth24) {
  const Ellipsoid e = shapeOf(GetParam());
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  const RadiusRange wide = planetRange(e);
  int checked = 0;
  for (const auto& path : testPaths(24)) {
    for (size_t i = 0; i + 1 < path.size(); ++i) {
      const NodeBounds parent = NodeBounds::forNode(m, path[i], wide, e);
      const std::array<NodeBounds, 4> fromParent = childBounds(m, path[i], parent, {wide, wide, wide, wide}, e);
      for (int q = 0; q < 4; ++q) {
        const NodeId child = path[i].child(q);
        const std::vector<glm::dvec3> points = terrainPoints(e, child, 5, {kMinHeight_m, 0.0, kMaxHeight_m});
        const NodeBounds own = NodeBounds::forNode(m, child, wide, e);
        const NodeBounds tight = NodeBounds::forNode(m, child, rangeOf(points), e);
        for (const glm::dvec3& p : points) {
          ASSERT_TRUE(parent.contains(p, 1e-6)) << "level " << int(child.level) << " face " << int(child.face);
          ASSERT_TRUE(own.contains(p, 1e-6));
          ASSERT_TRUE(fromParent[static_cast<size_t>(q)].contains(p, 1e-6));
          ASSERT_TRUE(tight.contains(p, 1e-6)) << "level " << int(child.level) << " face " << int(child.face);
          ++checked;
        }
        for (const glm::dvec3& c : tight.corners) {
          ASSERT_LE(glm::length(c - tight.sphereCentre), tight.sphereRadius);
        }
      }
    }
  }
  EXPECT_GT(checked, 100000);
}

// How far the planes stand off the surface they bound, over a node's smooth ellipsoid (h = 0) patch:
// each plane within max(1e-3, 2.5 f) node widths (plus 1 cm) of the nearest surface point. On a sphere
// they touch it; on an ellipsoid a geocentric radius range is itself about f node widths thick over
// a smooth patch (the surface slopes against the spheres |p| = r), and the side planes move out by
// the bound of the edges' bulge (NodeBounds::tighten).
TEST_P(EllipsoidBounds, PlanesStayCloseToTheSurface) {
  const Ellipsoid e = shapeOf(GetParam());
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  double worstSide = 0.0, worstCap = 0.0, worstDiagonal = 0.0;
  for (const auto& path : testPaths(20)) {
    for (const NodeId& id : path) {
      if (id.level < 4) continue;
      const std::vector<glm::dvec3> points = terrainPoints(e, id, 9, {0.0});
      const NodeBounds b = NodeBounds::forNode(m, id, rangeOf(points), e);
      const double width = nominalNodeWidth(id.level, kA_m);
      worstDiagonal = std::max(worstDiagonal, b.diagonal() / width);
      for (size_t k = 0; k < 6; ++k) {
        double gap = 1e300;
        for (const glm::dvec3& p : points) gap = std::min(gap, -(glm::dot(glm::dvec3(b.planes[k]), p) + b.planes[k].w));
        ASSERT_GE(gap, -1e-6);
        if (k < 4) worstSide = std::max(worstSide, gap / width);
        if (k >= 4) worstCap = std::max(worstCap, (gap - 0.01) / width);
      }
    }
  }
  RecordProperty("worst_side_gap_node_widths", std::to_string(worstSide));
  RecordProperty("worst_top_bottom_gap_node_widths", std::to_string(worstCap));
  EXPECT_LE(worstSide, std::max(1e-3, 2.5 * e.flattening())) << worstSide;
  EXPECT_LE(worstCap, std::max(1e-3, 2.5 * e.flattening())) << worstCap;
  // The bounding sphere stays about the node's size (the LOD ranges grow with the largest diagonal).
  RecordProperty("worst_diagonal_node_widths", std::to_string(worstDiagonal));
  EXPECT_LE(worstDiagonal, 2.0 * (1.0 + 2.5 * e.flattening())) << worstDiagonal;
}

// The visibility truth: for terrain no lower than h = 0 the occluder is the ellipsoid itself, and the
// segment camera -> p is visible when it misses its interior (in scaled space: the open unit ball).
bool visibleOverEllipsoid(const Ellipsoid& e, const glm::dvec3& camera, const glm::dvec3& p) {
  const glm::dvec3 s(1.0 / e.equatorialRadius_m(), 1.0 / e.equatorialRadius_m(), 1.0 / e.polarRadius_m());
  const glm::dvec3 c = camera * s, d = p * s - c;
  const double t = std::clamp(-glm::dot(c, d) / glm::dot(d, d), 0.0, 1.0);
  const glm::dvec3 closest = c + t * d;
  return glm::dot(closest, closest) >= 1.0 - 1e-12;
}

TEST_P(EllipsoidBounds, HorizonNeverDropsAVisibleNodeAtOneMetreAndZero) {
  const Ellipsoid e = shapeOf(GetParam());
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  std::mt19937_64 rng(77);
  std::vector<GeodeticPoint> sites = {{0, 0},   {0, 90},    {0, 180},      {0, -180}, {-0.0, 45},  {90, 0},
                                      {-90, 0}, {89.9, 10}, {-89.99, -70}, {45, 30},  {-45, -150}, {35.26, 72}};
  std::uniform_real_distribution<double> lat(-90.0, 90.0), lon(-180.0, 180.0);
  while (sites.size() < 40) sites.push_back({lat(rng), lon(rng)});
  int hidden = 0, samples = 0;
  for (const GeodeticPoint& site : sites) {
    for (double altitude : {0.0, 1.0}) {
      const glm::dvec3 camera = e.geocentricFromGeodetic({site.latitude_deg, site.longitude_deg, altitude});
      const HorizonCone cone(camera, e, 0.0);  // terrain nowhere below the ellipsoid
      ASSERT_TRUE(cone.enabled()) << "a camera on the surface still culls";
      const FacePoint below = m.locate(e.normalBelow(camera));
      std::vector<NodeId> nodes;
      for (int level : {0, 3, 6, 10, 14, 18}) {
        const NodeId id = nodeAt(below, level);
        nodes.push_back(id);
        for (int k = 0; k < 4; ++k) nodes.push_back(edgeNeighbour(id, k));
      }
      for (int i = 0; i < 30; ++i) nodes.push_back(testing::randomNodeAt(rng, static_cast<int>(rng() % 7)));
      for (const NodeId& id : nodes) {
        const std::vector<glm::dvec3> points = terrainPoints(e, id, 9, {0.0, 0.5, 300.0});
        const NodeBounds b = NodeBounds::forNode(m, id, rangeOf(points), e);
        const HorizonVisibility v = cone.classify(b);
        if (v == HorizonVisibility::kPartlyVisible) continue;
        if (v == HorizonVisibility::kHidden) ++hidden;
        for (const glm::dvec3& p : points) {
          ++samples;
          const bool visible = visibleOverEllipsoid(e, camera, p);
          ASSERT_FALSE(v == HorizonVisibility::kHidden && visible)
              << "dropped a visible node: site " << site.latitude_deg << "," << site.longitude_deg << " altitude "
              << altitude << " level " << int(id.level);
          ASSERT_FALSE(cone.isHidden(p) && visible);
        }
      }
    }
  }
  EXPECT_GT(hidden, 500);  // it does cull
  EXPECT_GT(samples, 100000);
}

// Deep terrain (minimum -500 m): the occluder shrinks (s E), and nothing visible over the real
// parallel surface at -500 m is dropped; the truth is the lowest height along the line of sight.
double lowestHeightOnSegment(const Ellipsoid& e, const glm::dvec3& a, const glm::dvec3& b) {
  double lo = 0.0, hi = 1.0;
  constexpr int kSteps = 32;
  double best = 1e300, bestT = 0.0;
  for (int i = 0; i <= kSteps; ++i) {
    const double t = double(i) / kSteps;
    const double h = e.heightAbove_m(a + t * (b - a));
    if (h < best) best = h, bestT = t;
  }
  lo = std::max(0.0, bestT - 1.0 / kSteps);
  hi = std::min(1.0, bestT + 1.0 / kSteps);
  for (int i = 0; i < 60; ++i) {  // golden section: the height is unimodal near its minimum
    const double m1 = lo + 0.382 * (hi - lo), m2 = lo + 0.618 * (hi - lo);
    if (e.heightAbove_m(a + m1 * (b - a)) < e.heightAbove_m(a + m2 * (b - a)))
      hi = m2;
    else
      lo = m1;
  }
  return std::min(best, e.heightAbove_m(a + 0.5 * (lo + hi) * (b - a)));
}

TEST_P(EllipsoidBounds, HorizonWithTerrainBelowTheEllipsoidIsConservative) {
  const Ellipsoid e = shapeOf(GetParam());
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  std::mt19937_64 rng(78);
  const double minHeight = -500.0;
  int hidden = 0;
  for (const GeodeticPoint& site : {GeodeticPoint{0, 0}, GeodeticPoint{90, 0}, GeodeticPoint{-90, 0},
                                    GeodeticPoint{45, -180}, GeodeticPoint{-30, 100}}) {
    const glm::dvec3 camera = e.geocentricFromGeodetic({site.latitude_deg, site.longitude_deg, minHeight + 1.0});
    const HorizonCone cone(camera, e, minHeight);
    ASSERT_TRUE(cone.enabled());
    const FacePoint below = m.locate(e.normalBelow(camera));
    std::vector<NodeId> nodes;
    for (int level : {3, 8, 13}) {
      const NodeId id = nodeAt(below, level);
      nodes.push_back(id);
      for (int k = 0; k < 4; ++k) nodes.push_back(edgeNeighbour(id, k));
    }
    for (int i = 0; i < 20; ++i) nodes.push_back(testing::randomNodeAt(rng, 2 + static_cast<int>(rng() % 4)));
    for (const NodeId& id : nodes) {
      const std::vector<glm::dvec3> points = terrainPoints(e, id, 5, {minHeight, 0.0, 2000.0});
      const NodeBounds b = NodeBounds::forNode(m, id, rangeOf(points), e);
      if (cone.classify(b) != HorizonVisibility::kHidden) continue;
      ++hidden;
      for (const glm::dvec3& p : points) {
        ASSERT_LT(lowestHeightOnSegment(e, camera, p), minHeight + 1e-6)
            << "dropped a node visible over the terrain floor, level " << int(id.level);
      }
    }
  }
  EXPECT_GT(hidden, 20);
}

TEST(EllipsoidBounds, SphereShapeGivesTheSphericalBoundsBitForBit) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  std::mt19937_64 rng(3);
  const RadiusRange r{6371000.0 - 11000.0, 6371000.0 + 9000.0};
  for (int i = 0; i < 200; ++i) {
    const NodeId id = testing::randomNodeAt(rng, static_cast<int>(rng() % 20));
    const NodeBounds plain = NodeBounds::forNode(m, id, r);
    const NodeBounds sphere = NodeBounds::forNode(m, id, r, Ellipsoid::sphere(6371000.0));
    for (size_t k = 0; k < 8; ++k) ASSERT_TRUE(testing::bitEqual(plain.corners[k], sphere.corners[k]));
    ASSERT_EQ(plain.sphereRadius, sphere.sphereRadius);
    const glm::dvec3 camera = testing::randomDirection(rng) * (6371000.0 - 11000.0 + 100.0);
    const HorizonCone a(camera, r.min_m), b(camera, Ellipsoid::sphere(6371000.0), -11000.0);
    ASSERT_EQ(a.classify(plain), b.classify(plain));
  }
}

}  // namespace
}  // namespace globe
