// The geographic tiling of baked tilesets, bake plans and shards, and the horizon-occlusion point
// (planet/tiling, issue 19).
#include "planet/tiling/bake_plan.h"
#include "planet/tiling/horizon_occlusion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include <glm/geometric.hpp>

namespace globe {
namespace {

TEST(GeographicTiling, TwoRootTilesSplitInFour) {
  EXPECT_EQ(tilesAcross(0), 2u);
  EXPECT_EQ(tilesDown(0), 1u);
  EXPECT_EQ(tilesAcross(3), 16u);
  const GeoRect east = tileRect({0, 1, 0});
  EXPECT_EQ(east.west_deg, 0.0);
  EXPECT_EQ(east.east_deg, 180.0);
  EXPECT_EQ(east.south_deg, -90.0);
  const GeoRect t = tileRect({2, 3, 1});  // TMS: y counts from the south
  EXPECT_EQ(t.west_deg, -45.0);
  EXPECT_EQ(t.south_deg, -45.0);
  EXPECT_EQ(t.north_deg, 0.0);
}

TEST(GeographicTiling, RegionsCoverTheOverlappingTiles) {
  const TileRange r = tilesCovering(3, {5.0, 44.0, 8.0, 47.0});
  EXPECT_EQ(r.x0, 8u);
  EXPECT_EQ(r.x1, 8u);
  EXPECT_EQ(r.y0, 5u);
  EXPECT_EQ(r.y1, 6u);                                              // 45 degrees is an edge: both rows
  const TileRange edge = tilesCovering(2, {0.0, 0.0, 45.0, 45.0});  // exactly one tile
  EXPECT_EQ(edge.count(), 1u);
  EXPECT_EQ(tilesCovering(4, {-180.0, -90.0, 180.0, 90.0}).count(), std::uint64_t(32) * 16);
}

TEST(GeographicTiling, NeighboursShareTheirEdgeSamplesBitForBit) {
  for (int level : {1, 7, 19}) {
    const std::uint32_t x = tilesAcross(level) / 3, y = tilesDown(level) / 3;
    for (int j = 0; j <= 64; ++j) {
      const LonLat a = tileSampleLonLat({level, x, y}, 64, 64, j);
      const LonLat b = tileSampleLonLat({level, x + 1, y}, 64, 0, j);
      EXPECT_EQ(a.lon_deg, b.lon_deg);
      EXPECT_EQ(a.lat_deg, b.lat_deg);
      const LonLat c = tileSampleLonLat({level, x, y}, 64, j, 64);
      const LonLat d = tileSampleLonLat({level, x, y + 1}, 64, j, 0);
      EXPECT_EQ(c.lon_deg, d.lon_deg);
      EXPECT_EQ(c.lat_deg, d.lat_deg);
    }
    // Across the antimeridian, and the apron clamped at the poles.
    const LonLat east = tileSampleLonLat({level, tilesAcross(level) - 1, 0}, 64, 64, 3);
    const LonLat west = tileSampleLonLat({level, 0, 0}, 64, 0, 3);
    EXPECT_EQ(east.lon_deg, west.lon_deg);
    EXPECT_EQ(east.lon_deg, -180.0);
    EXPECT_EQ(tileSampleLonLat({level, 0, tilesDown(level) - 1}, 64, 5, 65).lat_deg, 90.0);
  }
}

TEST(GeographicTiling, LevelErrorHalvesPerLevel) {
  EXPECT_NEAR(levelGeometricError_m(6371000.0, 0), 76981.1, 0.1);  // Cesium's estimate for Earth's radius
  EXPECT_DOUBLE_EQ(levelGeometricError_m(6371000.0, 14), levelGeometricError_m(6371000.0, 0) / 16384.0);
}

TEST(BakePlan, ParsesOptionsAndRefusesBadOnes) {
  EXPECT_EQ(parseBakeFormat("cog", "--format").value(), BakeFormat::Cog);
  EXPECT_FALSE(parseBakeFormat("png", "--format").ok());
  EXPECT_EQ(parseLevelRange("2..7", "--levels").value().last, 7);
  EXPECT_EQ(parseLevelRange("4", "--levels").value().first, 4);
  // 1e1, 0x3, 3.5 were read as 1, 0 and 3 (issue 40): levels are decimal digits only.
  for (const char* bad : {"7..2", "0..25", "-1..3", "a..b", "1..2..3", "1..2x", "", "1e1", "0x3", "3.5", "0..3.5", "+2",
                          " 2", "2..", "..2"}) {
    EXPECT_FALSE(parseLevelRange(bad, "--levels").ok()) << bad;
  }
  EXPECT_EQ(parseRegion("5,44,8,47", "--region").value().north_deg, 47.0);
  for (const char* bad : {"5,44,8", "8,44,5,47", "5,47,8,44", "-181,0,0,1", "0,0,1,91", "nan,0,1,1", "0,0,1,1,2"}) {
    EXPECT_FALSE(parseRegion(bad, "--region").ok()) << bad;
  }
  EXPECT_EQ(parseShard("2/5", "--shard").value().index, 2u);
  for (const char* bad : {"5/5", "0/0", "-1/3", "1/2x", "1 /2", "+1/2", "1of2"}) {
    EXPECT_FALSE(parseShard(bad, "--shard").ok()) << bad;
  }
  const Error e = parseShard("5/5", "--shard").error();
  EXPECT_EQ(e.field, "--shard");
  EXPECT_EQ(e.format().find('\n'), std::string::npos);
}

TEST(BakePlan, ShardsPartitionThePlan) {
  const BakePlan plan({0, 6}, {5.0, 40.0, 12.0, 47.0});
  EXPECT_EQ(plan.ranges().front().count(), 2u) << "level 0 is whole";
  std::set<std::tuple<int, std::uint32_t, std::uint32_t>> seen;
  std::size_t largest = 0, smallest = SIZE_MAX;
  std::tuple<int, std::uint32_t, std::uint32_t> previous{-1, 0, 0};
  for (std::uint64_t i = 0; i < plan.tileCount(); ++i) {  // plan order: level, then y, then x
    const TileId t = plan.tileAt(i);
    const std::tuple<int, std::uint32_t, std::uint32_t> key{t.level, t.y, t.x};
    EXPECT_LT(previous, key) << i;
    previous = key;
  }
  for (std::uint32_t k = 0; k < 7; ++k) {
    const std::uint64_t count = plan.tileCountOf({k, 7});
    largest = std::max<std::size_t>(largest, count);
    smallest = std::min<std::size_t>(smallest, count);
    for (std::uint64_t j = 0; j < count; ++j) {
      const TileId t = plan.tileOf({k, 7}, j);
      EXPECT_TRUE(seen.insert({t.level, t.x, t.y}).second) << "a tile in two shards";
    }
  }
  EXPECT_EQ(seen.size(), plan.tileCount());
  EXPECT_LE(largest - smallest, 1u) << "round robin balances the shards";
}

// The whole planet to level 24 is 2^49.4 tiles: never listed, a shard's last tile is computed at once.
TEST(BakePlan, HugePlansAreNeverListed) {
  const BakePlan plan({0, 24}, {-180.0, -90.0, 180.0, 90.0});
  std::uint64_t total = 0;
  for (int level = 0; level <= 24; ++level) total += 2ull << (2 * level);
  EXPECT_EQ(plan.tileCount(), total);
  const Shard last{999999, 1000000};
  const std::uint64_t count = plan.tileCountOf(last);
  EXPECT_EQ(count, (total - 999999 + 999999) / 1000000);
  const TileId t = plan.tileOf(last, count - 1);
  EXPECT_EQ(t.level, 24);
  EXPECT_LT(t.x, tilesAcross(24));
  EXPECT_LT(t.y, tilesDown(24));
  EXPECT_EQ(plan.tileAt(total - 1), (TileId{24, tilesAcross(24) - 1, tilesDown(24) - 1}));
  EXPECT_EQ(tilePath({3, 8, 5}, ".terrain"), "3/8/5.terrain");
}

// Brute force: from random viewers, whenever the horizon point is hidden behind the planet, every
// vertex is hidden too (the property a client relies on to cull the tile).
TEST(HorizonOcclusion, HiddenPointMeansHiddenVertices) {
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double radius = 1000.0;
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.2, 0.3, 0.9));
  std::vector<glm::dvec3> vertices;
  for (int k = 0; k < 200; ++k) {  // a patch around the axis, up to 5 % above the surface
    const glm::dvec3 d = glm::normalize(axis + 0.3 * glm::dvec3(u(rng), u(rng), u(rng)));
    vertices.push_back(d * radius * (1.0 + 0.025 * (u(rng) + 1.0)));
  }
  const auto h = horizonOcclusionPoint(vertices, glm::dvec3(radius), axis);
  ASSERT_TRUE(h.has_value());
  for (const glm::dvec3& v : vertices) EXPECT_TRUE(insideHorizonCone(v / radius, *h, 1e-9));
  // Segment a-b passes through the unit sphere.
  auto blocked = [](const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 d = b - a;
    const double t = std::clamp(-glm::dot(a, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(a + t * d) < 1.0;
  };
  int hidden = 0;
  for (int k = 0; k < 5000; ++k) {
    const glm::dvec3 viewer = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng))) * (1.01 + 4.0 * (u(rng) + 1.0));
    if (!blocked(viewer, *h)) continue;
    ++hidden;
    for (const glm::dvec3& v : vertices)
      ASSERT_TRUE(blocked(viewer, v / radius)) << "a vertex seen past a hidden point";
  }
  EXPECT_GT(hidden, 250);
  // A hemisphere admits no point.
  EXPECT_FALSE(horizonOcclusionPoint(std::vector<glm::dvec3>{glm::dvec3(0, 0, radius), glm::dvec3(radius, 0, 0)},
                                     glm::dvec3(radius), glm::dvec3(0, 0, 1))
                   .has_value());
}

}  // namespace
}  // namespace globe
