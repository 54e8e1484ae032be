// Imagery LOD (planet/imagery/imagery_selection.h): tiles refined by texel magnification, separate
// from the mesh's selection; cells meet neighbours at most one tile level apart; missing tiles fall
// back to resident ancestors and are asked for one level at a time.
#include "planet/imagery/imagery_selection.h"

#include "planet/lod/lod_ranges.h"
#include "planet/lod/selection.h"
#include "tests/support/lod_test_util.h"

#include <gtest/gtest.h>

#include <numbers>
#include <unordered_map>

namespace globe {
namespace {
using testing::kEarthRadius_m;

constexpr double kFov_rad = std::numbers::pi / 3.0;

ImagerySelector makeImagery(int maxLevel = kMaxNodeLevel, double magnification_px = 1.5) {
  ImageryConfig config;
  config.maxLevel = maxLevel;
  config.magnification_px = magnification_px;
  return ImagerySelector(config, kEarthRadius_m, -8000.0, 8000.0);
}

struct View {
  const char* name;
  double altitude_m;
};
constexpr View kViews[] = {{"orbit", 1.0e7}, {"100km", 1.0e5}, {"10km", 1.0e4}, {"1km", 1.0e3}};

// The mesh's selection and the imagery's for a camera `altitude_m` over (lat 20, lon 30), no frustum.
struct Scene {
  Selection mesh;
  ImagerySelection imagery;
  glm::dvec3 eye{0.0};
};
Scene select(double altitude_m, NodeResidency& tiles, int maxLevel = kMaxNodeLevel, double magnification_px = 1.5) {
  Scene s;
  testing::AllResident geometry;
  LodSelector selector = testing::earthSelector(20);
  s.eye = testing::fromLatLon(20.0, 30.0) * (kEarthRadius_m + altitude_m);
  EXPECT_TRUE(selector.select({s.eye, nullptr}, geometry, s.mesh).ok());
  ImagerySelector imagery = makeImagery(maxLevel, magnification_px);
  imagery.select(s.eye, altitude_m, pixelsPerRadian(720.0, kFov_rad), s.mesh.nodes, geometry, tiles, s.imagery);
  return s;
}

// The cell of drawn node `n`'s table entry c, as a node id kImageryCellLevels below n.
NodeId cellId(const SelectedNode& n, int c) {
  const uint32_t cx = uint32_t(c % kImageryCellsPerSide), cy = uint32_t(c / kImageryCellsPerSide);
  return {n.id.face, uint8_t(n.id.level + kImageryCellLevels), n.id.x * kImageryCellsPerSide + cx,
          n.id.y * kImageryCellsPerSide + cy};
}

TEST(ImagerySelection, MagnificationStaysWithinTheTargetWhenEveryTileIsResident) {
  for (const View& v : kViews) {
    testing::AllResident tiles;
    const Scene s = select(v.altitude_m, tiles);
    const ImageryStats& st = s.imagery.stats;
    EXPECT_EQ(st.capped, 0u) << v.name;
    EXPECT_EQ(st.fallbacks, 0u) << v.name;
    EXPECT_EQ(tiles.requests, 0) << v.name;
    EXPECT_GT(st.maxMagnification_px, 0.5) << v.name;
    EXPECT_LE(st.maxMagnification_px, 1.5 + 1e-9) << v.name;
    EXPECT_LE(st.p95Magnification_px, st.maxMagnification_px) << v.name;
    EXPECT_EQ(s.imagery.cells.size(), s.mesh.nodes.size() * kImageryCellsPerNode) << v.name;
  }
}

TEST(ImagerySelection, TilesAreTheirOwnLevelsNotTheMeshs) {
  // With coarse texels allowed, one tile covers many nodes (n to 1); with the default, near the
  // ground a node shows tiles below it (1 to n).
  testing::AllResident tiles;
  const Scene far = select(1.0e5, tiles, kMaxNodeLevel, 16.0);
  int coarser = 0, finer = 0;
  for (size_t k = 0; k < far.mesh.nodes.size(); ++k)
    coarser += far.imagery.cells[k * kImageryCellsPerNode].tile.level < far.mesh.nodes[k].id.level ? 1 : 0;
  EXPECT_GT(coarser, 0);
  const Scene near = select(1.0e3, tiles);
  for (size_t k = 0; k < near.mesh.nodes.size(); ++k)
    finer += near.imagery.cells[k * kImageryCellsPerNode].tile.level > near.mesh.nodes[k].id.level ? 1 : 0;
  EXPECT_GT(finer, 0);
  // Every cell's tile contains the cell.
  for (const Scene* s : {&far, &near}) {
    for (size_t k = 0; k < s->mesh.nodes.size(); ++k) {
      for (int c = 0; c < kImageryCellsPerNode; ++c) {
        const NodeId cell = cellId(s->mesh.nodes[k], c);
        const NodeId tile = s->imagery.cells[k * kImageryCellsPerNode + size_t(c)].tile;
        ASSERT_LE(tile.level, cell.level);
        EXPECT_EQ(cell.ancestor(tile.level).key(), tile.key());
      }
    }
  }
}

TEST(ImagerySelection, NeighbouringCellsDifferByAtMostOneTileLevelAcrossSeams) {
  // The fragments' blend to the parent's texels is seamless only between tiles one level apart.
  for (const View& v : kViews) {
    testing::AllResident tiles;
    const Scene s = select(v.altitude_m, tiles);
    std::unordered_map<uint64_t, int> tileLevelOfCell;
    for (size_t k = 0; k < s.mesh.nodes.size(); ++k)
      for (int c = 0; c < kImageryCellsPerNode; ++c)
        tileLevelOfCell[cellId(s.mesh.nodes[k], c).key()] =
            s.imagery.cells[k * kImageryCellsPerNode + size_t(c)].tile.level;
    int compared = 0;
    for (const auto& [key, level] : tileLevelOfCell) {
      const NodeId cell = NodeId::fromKey(key);
      for (int e = 0; e < 4; ++e) {
        const NodeId nb = edgeNeighbour(cell, e);
        for (int l = nb.level; l >= 0; --l) {
          auto it = tileLevelOfCell.find(nb.ancestor(l).key());
          if (it == tileLevelOfCell.end()) continue;
          EXPECT_LE(std::abs(it->second - level), 1) << v.name << " cell " << key;
          ++compared;
          break;
        }
      }
    }
    EXPECT_GT(compared, 1000) << v.name;
  }
}

TEST(ImagerySelection, MissingTilesFallBackToResidentAncestorsAndAreAskedForOneLevelAtATime) {
  testing::PartlyResident tiles(3, {});
  const Scene s = select(1.0e3, tiles);
  EXPECT_GT(s.imagery.stats.fallbacks, 0u);
  EXPECT_GT(s.imagery.stats.requests, 0u);
  for (const NodeId& asked : tiles.requested) {
    ASSERT_GT(asked.level, 0);
    EXPECT_TRUE(tiles.isResident(asked.parent())) << "requested a tile whose parent is not resident";
    EXPECT_FALSE(tiles.isResident(asked));
  }
  for (const ImageryCell& c : s.imagery.cells) {
    EXPECT_TRUE(c.resident);
    EXPECT_TRUE(tiles.isResident(c.tile));
  }
  // Fallbacks draw coarser texels: the bound says so.
  EXPECT_GT(s.imagery.stats.maxMagnification_px, 1.5);
}

TEST(ImagerySelection, CellsBeyondTheTableOrTheDeepestLevelAreCounted) {
  testing::AllResident tiles;
  const Scene capped = select(1.0e3, tiles, 12);
  EXPECT_GT(capped.imagery.stats.capped, 0u);
  EXPECT_LE(capped.imagery.stats.deepest, 12u);
  EXPECT_GT(capped.imagery.stats.maxMagnification_px, 1.5);
}

TEST(ImagerySelection, AdequateDistancesHalveWithEachLevel) {
  const ImagerySelector s = makeImagery();
  const double lambda = pixelsPerRadian(720.0, kFov_rad);
  for (int level = 1; level <= 20; ++level)
    EXPECT_DOUBLE_EQ(s.adequateFrom_m(level - 1, lambda), 2.0 * s.adequateFrom_m(level, lambda));
  // W(0) bounds a root's edges (the widest ~41.8 degrees of arc) with a 5 % margin.
  EXPECT_GT(s.levelWidth_m(0), 0.6 * (kEarthRadius_m + 8000.0));
  EXPECT_LT(s.levelWidth_m(0), 0.8 * (kEarthRadius_m + 8000.0));
}

}  // namespace
}  // namespace globe
