#include "planet/lod/roughness_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "planet/geometry/triacontahedron.h"
#include "planet/model/planet_file.h"
#include "planet/model/relief_roughness.h"
#include "tests/support/lod_test_util.h"

namespace globe {
namespace {

constexpr double kMinRadius_m = testing::kEarthRadius_m - 8000.0;

const RoughnessMap& syntheticMap() {
  static const std::shared_ptr<const RoughnessMap> map = testing::syntheticRoughnessMap(20, kMinRadius_m);
  return *map;
}

const ElevationModel& earthlike() {
  static const ElevationModel model(
      loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml").value());
  return model;
}

// (u, v) of parameter t along face edge e (testing::onEdge) as a vector.
glm::dvec2 onEdge(int e, double t) {
  const auto [u, v] = testing::onEdge(e, t);
  return {u, v};
}

TEST(RoughnessMap, SeamPointsAreStoredOnce) {
  const RoughnessMap& map = syntheticMap();
  const int inner = RoughnessMap::kCells - 1;  // points strictly inside a face edge
  EXPECT_EQ(map.pointCount(), size_t(kFaceCount * inner * inner + 60 * inner + kVertexCount));
  // Both faces of every seam name the same points along it, in reverse order.
  for (int f = 0; f < kFaceCount; ++f) {
    for (int e = 0; e < 4; ++e) {
      const FaceEdgeNeighbour nb = Triacontahedron::get().face(f).neighbour[size_t(e)];
      for (int k = 0; k <= RoughnessMap::kCells; ++k) {
        const glm::dvec2 a = onEdge(e, double(k) / RoughnessMap::kCells) * double(RoughnessMap::kCells);
        const glm::dvec2 b = onEdge(nb.edge, 1.0 - double(k) / RoughnessMap::kCells) * double(RoughnessMap::kCells);
        EXPECT_EQ(map.point(f, int(a.x), int(a.y)), map.point(nb.face, int(b.x), int(b.y)));
      }
    }
  }
}

TEST(RoughnessMap, RelativeRoughnessIsNormalisedPerDepth) {
  const RoughnessMap& map = syntheticMap();
  for (int d = 0; d <= map.maxDepth(); ++d) {
    const auto w = map.relative(d);
    EXPECT_EQ(*std::max_element(w.begin(), w.end()), 1.0F);
    EXPECT_NEAR(*std::min_element(w.begin(), w.end()), 0.04F, 1e-6);  // 0.01 / 0.25
  }
}

TEST(RoughnessMap, NodeMaximumBoundsTheFieldAndCornersInterpolate) {
  const RoughnessMap& map = syntheticMap();
  const auto w = map.relative(10);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 4000; ++k) {
    const int level = RoughnessMap::firstDepth() + int(unit(rng) * 10.0);
    const FacePoint p = RhombusFaceMapping::get().locate(testing::randomDirection(rng));
    const NodeId node = nodeAt(p, level);
    const double top = map.maxOver(w, node);
    const std::array<double, 4> c = map.corners(w, node);
    EXPECT_EQ(c[3], map.interpolate(w, node.face, node.uMin() + node.size(), node.vMin() + node.size()));
    const double u = node.uMin() + node.size() * unit(rng), v = node.vMin() + node.size() * unit(rng);
    EXPECT_LE(map.interpolate(w, node.face, u, v), top + 1e-12) << "level " << level;
  }
}

TEST(RoughnessMap, SlopeBoundsNeighbouringPointsAlsoAcrossSeams) {
  const RoughnessMap& map = syntheticMap();
  const auto w = map.relative(12);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const glm::dvec3 a = testing::randomDirection(rng);
    const glm::dvec3 b = glm::normalize(a + 0.02 * unit(rng) * testing::randomDirection(rng));
    const FacePoint pa = RhombusFaceMapping::get().locate(a), pb = RhombusFaceMapping::get().locate(b);
    const double change = std::abs(map.interpolate(w, pa.face, pa.u, pa.v) - map.interpolate(w, pb.face, pb.u, pb.v));
    worst = std::max(worst, change / (glm::length(a - b) * kMinRadius_m));
  }
  EXPECT_GT(worst, 0.0);
  EXPECT_LE(worst, map.slope(12));
  std::printf("[ info ] steepest sampled change %.3g per metre, bound %.3g\n", worst, map.slope(12));
}

TEST(RoughnessMap, BothFacesOfASeamInterpolateTheSameValue) {
  const RoughnessMap& map = syntheticMap();
  const auto w = map.relative(8);
  for (int f = 0; f < kFaceCount; ++f) {
    for (int e = 0; e < 4; ++e) {
      const FaceEdgeNeighbour nb = Triacontahedron::get().face(f).neighbour[size_t(e)];
      for (double t : {0.1, 0.337, 0.5, 0.77}) {
        const glm::dvec2 a = onEdge(e, t), b = onEdge(nb.edge, 1.0 - t);
        EXPECT_NEAR(map.interpolate(w, f, a.x, a.y), map.interpolate(w, nb.face, b.x, b.y), 1e-9);
      }
    }
  }
}

TEST(ReliefRoughness, EarthlikeMountainsAreRougherThanPlainsAndSea) {
  const std::shared_ptr<const RoughnessMap> map = reliefRoughnessMap(earthlike(), 16, 24);
  ASSERT_NE(map, nullptr);
  // Per depth: a spread between the roughest and the smoothest places (sea: the sphere's sag only).
  for (int d : {8, 14, 20}) {
    const auto w = map->relative(d);
    const auto [lo, hi] = std::minmax_element(w.begin(), w.end());
    EXPECT_EQ(*hi, 1.0F);
    EXPECT_LT(*lo, 0.05F) << "depth " << d;
    size_t rough = 0;
    for (float x : w) rough += x > 0.5F ? 1 : 0;
    EXPECT_GT(rough, 0u);
    EXPECT_LT(rough, w.size() / 2) << "depth " << d << ": most of the planet is sea or plain";
  }
}

TEST(ReliefRoughness, PlanetsWithSourcesKeepPerDepthRanges) {
  auto planet = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earth-dem.toml");
  ASSERT_TRUE(planet.ok()) << planet.error().message;
  EXPECT_EQ(reliefRoughnessMap(ElevationModel(*planet), 16, 20), nullptr);
}

}  // namespace
}  // namespace globe
