#include "planet/geometry/face_mapping.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "tests/support/lod_test_util.h"

namespace globe {
namespace {

using testing::fromLatLon;
using testing::randomDirection;

using testing::bitEqual;
using testing::onEdge;

TEST(FaceMapping, SharedEdgePointsBitIdenticalAcrossAllSixtyPairings) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  const Triacontahedron& t = Triacontahedron::get();
  std::mt19937_64 rng(1);
  int compared = 0;
  for (int f = 0; f < kFaceCount; ++f) {
    for (int e = 0; e < 4; ++e) {
      const FaceEdgeNeighbour& n = t.face(f).neighbour[static_cast<size_t>(e)];
      for (int level : {0, 1, 2, 5, 10, 20, 26}) {
        const uint64_t cells = uint64_t{1} << level;
        std::vector<uint64_t> ks;
        if (cells <= 64) {
          for (uint64_t k = 0; k <= cells; ++k) ks.push_back(k);
        } else {
          ks = {0, 1, cells / 2, cells - 1, cells};
          for (int i = 0; i < 60; ++i) ks.push_back(rng() % (cells + 1));
        }
        for (uint64_t k : ks) {
          const double s = std::ldexp(static_cast<double>(k), -level);
          const auto [u, v] = onEdge(e, s);
          const auto [un, vn] = onEdge(n.edge, n.reversed ? 1.0 - s : s);
          const glm::dvec3 a = m.unitPoint(f, u, v);
          const glm::dvec3 b = m.unitPoint(n.face, un, vn);
          ASSERT_TRUE(bitEqual(a, b)) << "face " << f << " edge " << e << " level " << level << " k " << k;
          ASSERT_TRUE(bitEqual(m.flatPoint(f, u, v), m.flatPoint(n.face, un, vn)));
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 10000);
}

TEST(FaceMapping, VerticesBitIdenticalFromEveryFace) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  const Triacontahedron& t = Triacontahedron::get();
  const double cu[4] = {0, 1, 1, 0};
  const double cv[4] = {0, 0, 1, 1};
  std::array<int, kVertexCount> seen{};
  std::array<glm::dvec3, kVertexCount> first{};
  for (int f = 0; f < kFaceCount; ++f) {
    for (int c = 0; c < 4; ++c) {
      const int v = t.face(f).vertex[static_cast<size_t>(c)];
      const glm::dvec3 p = m.unitPoint(f, cu[c], cv[c]);
      EXPECT_TRUE(bitEqual(m.flatPoint(f, cu[c], cv[c]), t.vertex(v)));
      EXPECT_NEAR(glm::length(p - t.vertexDirection(v)), 0.0, 4e-16);
      if (seen[static_cast<size_t>(v)]++ == 0) first[static_cast<size_t>(v)] = p;
      EXPECT_TRUE(bitEqual(p, first[static_cast<size_t>(v)])) << "vertex " << v;
    }
  }
}

TEST(FaceMapping, NeighbourNodesShareCornersExactly) {
  const FaceMapping& m = RhombusFaceMapping::get();
  std::mt19937_64 rng(7);
  int checked = 0;
  for (int level : {0, 1, 3, 8, 16, 20, 24, 26}) {
    for (int f = 0; f < kFaceCount; ++f) {
      const uint32_t last = (uint32_t{1} << level) - 1;
      std::uniform_int_distribution<uint32_t> cell(0, last);
      // Seam and corner nodes first, then random ones.
      const NodeId nodes[] = {
          {uint8_t(f), uint8_t(level), 0, 0},         {uint8_t(f), uint8_t(level), last, 0},
          {uint8_t(f), uint8_t(level), last, last},   {uint8_t(f), uint8_t(level), 0, last},
          {uint8_t(f), uint8_t(level), cell(rng), 0}, {uint8_t(f), uint8_t(level), cell(rng), cell(rng)}};
      for (const NodeId& id : nodes) {
        ASSERT_TRUE(id.isValid());
        for (int e = 0; e < 4; ++e) {
          const NodeId nb = edgeNeighbour(id, e);
          ASSERT_TRUE(nb.isValid());
          ASSERT_EQ(nb.level, id.level);
          // The neighbour's neighbour across some edge is the node again.
          int back = -1;
          for (int e2 = 0; e2 < 4; ++e2) {
            if (edgeNeighbour(nb, e2) == id) back = e2;
          }
          ASSERT_GE(back, 0) << "face " << f << " level " << level << " edge " << e;
          // The shared edge: our corners e, e+1 are its corners back+1, back.
          EXPECT_TRUE(bitEqual(nodeCornerDirection(m, id, e), nodeCornerDirection(m, nb, (back + 1) % 4)));
          EXPECT_TRUE(bitEqual(nodeCornerDirection(m, id, (e + 1) % 4), nodeCornerDirection(m, nb, back)));
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 5000);
}

TEST(FaceMapping, ChildCornersAreParentEdgeMidpointsAndCentre) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const int level = static_cast<int>(rng() % 20);
    const NodeId p = testing::randomNodeAt(rng, level);
    const double u0 = p.uMin(), v0 = p.vMin(), s = p.size();
    const glm::dvec3 a = m.flatPoint(p.face, u0, v0), b = m.flatPoint(p.face, u0 + s, v0);
    const glm::dvec3 c = m.flatPoint(p.face, u0 + s, v0 + s), d = m.flatPoint(p.face, u0, v0 + s);
    EXPECT_NEAR(glm::length(m.flatPoint(p.face, u0 + s / 2, v0) - 0.5 * (a + b)), 0.0, 4e-16);
    EXPECT_NEAR(glm::length(m.flatPoint(p.face, u0 + s / 2, v0 + s / 2) - 0.25 * (a + b + c + d)), 0.0, 4e-16);
    EXPECT_NEAR(glm::length(m.flatPoint(p.face, u0, v0 + s / 2) - 0.5 * (a + d)), 0.0, 4e-16);
  }
}

TEST(FaceMapping, GridAxesAreCounterClockwiseOutside) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  for (int f = 0; f < kFaceCount; ++f) {
    const glm::dvec3 p = m.unitPoint(f, 0.5, 0.5);
    const glm::dvec3 du = m.unitPoint(f, 0.51, 0.5) - p;
    const glm::dvec3 dv = m.unitPoint(f, 0.5, 0.51) - p;
    EXPECT_GT(glm::dot(glm::cross(du, dv), p), 0.0);
    EXPECT_GT(glm::dot(m.faceNormal(f), p), 0.9);
  }
}

TEST(FaceMapping, LocateInvertsUnitPoint) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  std::vector<glm::dvec3> directions = {{0, 0, 1},
                                        {0, 0, -1},
                                        {1, 0, 0},
                                        {-1, 0, 0},
                                        {0, 1, 0},
                                        {0, -1, 0},
                                        fromLatLon(0, 180),
                                        fromLatLon(0, -180),
                                        fromLatLon(45, 180),
                                        fromLatLon(-89.999999, 179.9999999),
                                        fromLatLon(89.9999999, -45)};
  for (int v = 0; v < kVertexCount; ++v) directions.push_back(Triacontahedron::get().vertexDirection(v));
  for (int f = 0; f < kFaceCount; ++f) {  // seam midpoints and near-seam points
    for (double s : {0.5, 0.125, 1e-9}) directions.push_back(m.unitPoint(f, s, 0.0));
  }
  std::mt19937_64 rng(3);
  for (int i = 0; i < 3000; ++i) directions.push_back(randomDirection(rng));
  for (const glm::dvec3& d : directions) {
    const FacePoint p = m.locate(d * 6371000.0);
    ASSERT_GE(p.face, 0);
    ASSERT_LT(p.face, kFaceCount);
    EXPECT_NEAR(glm::length(m.unitPoint(p.face, p.u, p.v) - d), 0.0, 2e-15);
    // The leaf node at level 20 contains the direction (side planes).
    const NodeId leaf = nodeAt(p, 20);
    ASSERT_TRUE(leaf.isValid());
    for (int e = 0; e < 4; ++e) {
      const glm::dvec3 a = nodeCornerDirection(m, leaf, e), b = nodeCornerDirection(m, leaf, (e + 1) % 4);
      EXPECT_LE(glm::dot(glm::cross(b - a, a), d), 1e-15);
    }
  }
  // Interior points map back to the same face and (u, v).
  for (int i = 0; i < 2000; ++i) {
    const int f = static_cast<int>(rng() % 30);
    const double u = 0.01 + 0.98 * static_cast<double>(rng() % 100000) / 1e5;
    const double v = 0.01 + 0.98 * static_cast<double>(rng() % 100000) / 1e5;
    const FacePoint p = m.locate(m.unitPoint(f, u, v));
    EXPECT_EQ(p.face, f);
    EXPECT_NEAR(p.u, u, 1e-14);
    EXPECT_NEAR(p.v, v, 1e-14);
  }
}

TEST(FaceMapping, GpuCornersCarryVertexIndices) {
  const RhombusFaceMapping& m = RhombusFaceMapping::get();
  static_assert(sizeof(FaceCornersGpu) == 128, "std430 FaceCorners is 4 dvec4");
  for (int f = 0; f < kFaceCount; ++f) {
    const FaceCornersGpu g = m.gpuCorners(f);
    for (size_t c = 0; c < 4; ++c) {
      const int v = Triacontahedron::get().face(f).vertex[c];
      EXPECT_EQ(g.corner[c].w, static_cast<double>(v));
      EXPECT_TRUE(bitEqual(glm::dvec3(g.corner[c]), Triacontahedron::get().vertex(v)));
    }
  }
}

TEST(NodeId, KeyRoundTripAndHierarchy) {
  std::mt19937_64 rng(5);
  for (int i = 0; i < 10000; ++i) {
    const int level = static_cast<int>(rng() % (kMaxNodeLevel + 1));
    const NodeId id = testing::randomNodeAt(rng, level);
    ASSERT_TRUE(id.isValid());
    EXPECT_EQ(NodeId::fromKey(id.key()), id);
    if (level < kMaxNodeLevel) {
      for (int q = 0; q < 4; ++q) {
        EXPECT_EQ(id.child(q).parent(), id);
        EXPECT_EQ(id.child(q).quadrant(), q);
        EXPECT_TRUE(id.isAncestorOf(id.child(q)));
      }
    }
  }
  const NodeId deepest{29, kMaxNodeLevel, (1u << kMaxNodeLevel) - 1, (1u << kMaxNodeLevel) - 1};
  EXPECT_EQ(NodeId::fromKey(deepest.key()), deepest);
  EXPECT_FALSE((NodeId{30, 0, 0, 0}).isValid());
  EXPECT_FALSE((NodeId{0, 2, 4, 0}).isValid());
}

}  // namespace
}  // namespace globe
