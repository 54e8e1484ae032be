#include "planet/geometry/triacontahedron.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "tests/support/lod_test_util.h"

namespace globe {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

double latitudeDeg(const glm::dvec3& d) { return std::asin(std::clamp(d.z, -1.0, 1.0)) * kDeg; }
double longitudeDeg(const glm::dvec3& d) { return std::atan2(d.y, d.x) * kDeg; }

TEST(Triacontahedron, CountsAndDegrees) {
  const Triacontahedron& t = Triacontahedron::get();
  std::array<int, kVertexCount> degree{};
  for (int f = 0; f < kFaceCount; ++f) {
    std::set<int> distinct;
    for (int v : t.face(f).vertex) {
      ASSERT_GE(v, 0);
      ASSERT_LT(v, kVertexCount);
      distinct.insert(v);
      ++degree[static_cast<size_t>(v)];
    }
    EXPECT_EQ(distinct.size(), 4u);
    // Corners 0 and 2 five-fold, 1 and 3 three-fold.
    EXPECT_TRUE(Triacontahedron::isFiveFold(t.face(f).vertex[0]));
    EXPECT_FALSE(Triacontahedron::isFiveFold(t.face(f).vertex[1]));
    EXPECT_TRUE(Triacontahedron::isFiveFold(t.face(f).vertex[2]));
    EXPECT_FALSE(Triacontahedron::isFiveFold(t.face(f).vertex[3]));
  }
  for (int v = 0; v < kVertexCount; ++v) EXPECT_EQ(degree[static_cast<size_t>(v)], v < 12 ? 5 : 3) << v;
}

TEST(Triacontahedron, EveryEdgeSharedByTwoFacesWithOppositeDirection) {
  const Triacontahedron& t = Triacontahedron::get();
  std::map<std::pair<int, int>, int> directed;
  for (int f = 0; f < kFaceCount; ++f) {
    for (int e = 0; e < 4; ++e) {
      const int a = t.face(f).vertex[static_cast<size_t>(e)];
      const int b = t.face(f).vertex[static_cast<size_t>((e + 1) % 4)];
      ++directed[{a, b}];
      const FaceEdgeNeighbour& n = t.face(f).neighbour[static_cast<size_t>(e)];
      EXPECT_NE(n.face, f);
      EXPECT_TRUE(n.reversed);
      const auto& g = t.face(n.face);
      EXPECT_EQ(g.vertex[n.edge], b);
      EXPECT_EQ(g.vertex[(n.edge + 1u) % 4u], a);
      // And back.
      EXPECT_EQ(g.neighbour[n.edge].face, f);
      EXPECT_EQ(g.neighbour[n.edge].edge, e);
    }
  }
  EXPECT_EQ(directed.size(), 120u);  // 60 edges, each once per direction: consistent orientation
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
  }
}

TEST(Triacontahedron, FlatRhombiWithSourceAngles) {
  const Triacontahedron& t = Triacontahedron::get();
  for (int f = 0; f < kFaceCount; ++f) {
    std::array<glm::dvec3, 4> c;
    for (size_t i = 0; i < 4; ++i) c[i] = t.vertex(t.face(f).vertex[i]);
    const glm::dvec3 normal = glm::normalize(glm::cross(c[1] - c[0], c[3] - c[0]));
    EXPECT_GT(glm::dot(normal, c[0] + c[2]), 0.0) << "counter-clockwise seen from outside";
    EXPECT_NEAR(glm::dot(normal, c[2] - c[0]), 0.0, 1e-15) << "planar";
    const double side = glm::length(c[1] - c[0]);
    for (size_t i = 0; i < 4; ++i) {
      EXPECT_NEAR(glm::length(c[(i + 1) % 4] - c[i]), side, 1e-15);
      const glm::dvec3 a = glm::normalize(c[(i + 1) % 4] - c[i]);
      const glm::dvec3 b = glm::normalize(c[(i + 3) % 4] - c[i]);
      const double angle = std::acos(glm::dot(a, b)) * kDeg;
      EXPECT_NEAR(angle, i % 2 == 0 ? 63.4349488 : 116.5650512, 1e-6) << "face " << f << " corner " << i;
    }
  }
  EXPECT_NEAR(t.edgeArc() * kDeg, 37.3773681, 1e-6);
  EXPECT_NEAR(t.edgeArc() * testing::kEarthRadius_m, 4156.0e3, 1e3);
}

TEST(Triacontahedron, OrientationTable) {
  const Triacontahedron& t = Triacontahedron::get();
  const double ring = std::atan(0.5) * kDeg;  // 26.565°
  struct Row {
    int vertex;
    double lat, lon;
  };
  const Row rows[] = {{0, 90, 0},      {1, ring, 0},     {2, ring, 72},    {3, ring, 144},
                      {4, ring, -144}, {5, ring, -72},   {6, -ring, 36},   {7, -ring, 108},
                      {8, -ring, 180}, {9, -ring, -108}, {10, -ring, -36}, {11, -90, 0}};
  // Three-fold vertices pinned by number (the docs/lod.md table): 4 decimals.
  const Row threeFold[] = {{12, 52.6226, 36},  {15, 52.6226, 180},   {19, -10.8123, 0},
                           {22, 10.8123, 180}, {25, -10.8123, -144}, {31, -52.6226, -72}};
  for (const Row& r : threeFold) {
    const glm::dvec3 d = t.vertexDirection(r.vertex);
    EXPECT_NEAR(latitudeDeg(d), r.lat, 1e-4) << r.vertex;
    EXPECT_NEAR(std::abs(longitudeDeg(d)) == 180.0 ? 180.0 : longitudeDeg(d), r.lon, 1e-4) << r.vertex;
  }
  for (const Row& r : rows) {
    const glm::dvec3 d = t.vertexDirection(r.vertex);
    EXPECT_NEAR(latitudeDeg(d), r.lat, 1e-12) << r.vertex;
    if (std::abs(r.lat) < 90) {
      EXPECT_NEAR(longitudeDeg(d), r.lon, 1e-12) << r.vertex;
    }
  }
  EXPECT_EQ(t.vertex(0), glm::dvec3(0, 0, 1));
  EXPECT_EQ(t.vertex(11), glm::dvec3(0, 0, -1));
  EXPECT_EQ(t.vertex(8).y, 0.0) << "the 180° vertex sits exactly on the antimeridian";
  // Three-fold vertices: 5 at +52.62°, 5 at +10.81°, 5 at -10.81°, 5 at -52.62° latitude.
  std::map<long, int> latitudes;
  for (int v = 12; v < 32; ++v) {
    EXPECT_NEAR(glm::length(t.vertex(v)), t.threeFoldRadius(), 1e-15);
    ++latitudes[std::lround(latitudeDeg(t.vertexDirection(v)) * 100)];
  }
  EXPECT_EQ(latitudes.size(), 4u);
  EXPECT_EQ(latitudes[5262], 5);
  EXPECT_EQ(latitudes[1081], 5);
  EXPECT_EQ(latitudes[-1081], 5);
  EXPECT_EQ(latitudes[-5262], 5);
}

TEST(Triacontahedron, SphericalFaceAreasSumToFourPi) {
  double total = 0.0;
  for (int f = 0; f < kFaceCount; ++f) {
    const double area = testing::nodeSolidAngle({static_cast<uint8_t>(f), 0, 0, 0});
    EXPECT_NEAR(area, 4.0 * std::numbers::pi / 30.0, 1e-13) << f;
    total += area;
  }
  EXPECT_NEAR(total, 4.0 * std::numbers::pi, 1e-12);
}

}  // namespace
}  // namespace globe
