// Baked tiles checked by our own decoder (planet/tiling/quantized_mesh_decoder.h) and by GDAL: header fields, the
// horizon-occlusion point, watertight edges between neighbours, heights against the CPU model, GPU
// heights equal to the CPU reference, deterministic bytes, valid COGs (issue 19).
#include "engine/bake/baker.h"
#include "engine/bake/cog_tile.h"
#include "engine/bake/tile_grid.h"
#include "planet/camera/camera.h"
#include "planet/core/atomic_file.h"
#include "planet/model/planet_file.h"
#include "planet/tiling/horizon_occlusion.h"
#include "planet/tiling/quantized_mesh_decoder.h"
#include "tests/support/gpu_test.h"
#include "tests/support/temp_dir.h"

#include <gdal.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>

#include <glm/geometric.hpp>

namespace globe::testing {
namespace {

const PlanetDescription& earthlike() {
  static const PlanetDescription planet = [] {
    auto p = loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
    if (!p) throw std::runtime_error(p.error().format());
    return *p;
  }();
  return planet;
}

Status writeFile(const std::string& path, std::string_view bytes) { return writeFileAtomically(path, bytes, "tile"); }

BakeSettings settingsFor(BakeFormat format, const std::string& dir) {
  BakeSettings s;
  s.format = format;
  s.levels = {0, 5};
  s.region = {0.0, 40.0, 12.0, 50.0};
  s.out_dir = dir;
  s.threads = 2;
  return s;
}

// One quantized-mesh bake per test process, decoded.
struct Baked {
  TempDir dir{"bake_tiles_qm"};
  std::map<std::tuple<int, std::uint32_t, std::uint32_t>, DecodedMesh> tiles;
};

class BakeTilesTest : public GpuTest {
 protected:
  const Baked& baked() {
    static std::unique_ptr<Baked> b;  // destroyed at exit, removing its directory
    if (b == nullptr) {
      b = std::make_unique<Baked>();
      GpuHeightSampler heights(device(), earthlikeModel());
      auto summary = runBake(earthlike(), heights, settingsFor(BakeFormat::QuantizedMesh, b->dir.str()), writeFile);
      EXPECT_TRUE(summary.ok()) << summary.error().format();
      for (const auto& entry : std::filesystem::recursive_directory_iterator(b->dir.str())) {
        if (entry.path().extension() != ".terrain") continue;
        const auto rel = std::filesystem::relative(entry.path(), b->dir.str());
        auto it = rel.begin();
        const int level = std::stoi((it++)->string());
        const auto x = std::uint32_t(std::stoul((it++)->string()));
        const auto y = std::uint32_t(std::stoul(it->stem().string()));
        std::string why;
        auto mesh = decodeQuantizedMesh(readFileBytes(entry.path()), &why);
        EXPECT_TRUE(mesh.has_value()) << rel << ": " << why;
        if (mesh) b->tiles[{level, x, y}] = std::move(*mesh);
      }
    }
    return *b;
  }
};

// The grid sample a vertex stands for (vertices are the grid's, u/v rounded from i/cells).
glm::ivec2 gridIndex(const DecodedMesh& m, std::size_t k) {
  return {int(std::lround(m.u[k] * double(kMeshCells) / 32767.0)),
          int(std::lround(m.v[k] * double(kMeshCells) / 32767.0))};
}

// Where a client draws vertex k: u/v over the tile's rectangle, at the dequantized height.
glm::dvec3 vertexPosition(const TileId& t, const DecodedMesh& m, std::size_t k, double radius_m) {
  const GeoRect r = tileRect(t);
  const double lon = r.west_deg + m.u[k] / 32767.0 * (r.east_deg - r.west_deg);
  const double lat = r.south_deg + m.v[k] / 32767.0 * (r.north_deg - r.south_deg);
  return directionFromLatLon(lat, lon) * (radius_m + m.height_m(k));
}

TEST_F(BakeTilesTest, GpuHeightsEqualTheCpuReference) {
  std::vector<glm::dvec3> directions;
  for (const TileId& t : {TileId{0, 0, 0}, TileId{3, 8, 5}, TileId{12, 4200, 2900}, TileId{20, 1 << 20, 1 << 19}}) {
    appendGridDirections(t, kMeshCells, directions);
  }
  appendCogDirections({6, 70, 40}, directions);
  GpuHeightSampler gpu(device(), earthlikeModel());
  CpuHeightSampler cpu(earthlikeModel(), 2);
  const auto a = gpu.heights_m(directions);
  const auto b = cpu.heights_m(directions);
  ASSERT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(a[k] - b[k]));
  EXPECT_LE(worst, 1e-6) << "over " << a.size() << " samples";
}

TEST_F(BakeTilesTest, HeaderFieldsDescribeTheVertices) {
  const double r = earthlike().radius_m;
  ASSERT_GT(baked().tiles.size(), 15u);
  for (const auto& [key, m] : baked().tiles) {
    const TileId t{std::get<0>(key), std::get<1>(key), std::get<2>(key)};
    SCOPED_TRACE(tilePath(t, ""));
    ASSERT_GE(m.u.size(), 4u * kMeshCells);
    EXPECT_TRUE(m.has_normals);
    EXPECT_LT(m.min_height, m.max_height);
    EXPECT_EQ(m.center, m.sphere_center);
    for (std::size_t k = 0; k < m.u.size(); ++k) {
      const glm::dvec3 p = vertexPosition(t, m, k, r);
      EXPECT_LE(glm::length(p - m.sphere_center), m.sphere_radius * (1 + 1e-12) + 1e-6);
      EXPECT_GE(m.height_m(k), m.min_height);
      EXPECT_LE(m.height_m(k), m.max_height);
      EXPECT_GT(glm::dot(m.normals[k], glm::normalize(p)), 0.5) << "normal " << k << " points away from up";
    }
    for (std::uint32_t index : m.indices) EXPECT_LT(index, m.u.size());
  }
}

TEST_F(BakeTilesTest, EveryVertexIsInsideTheHorizonPointsCone) {
  const double r = earthlike().radius_m;
  for (const auto& [key, m] : baked().tiles) {
    const TileId t{std::get<0>(key), std::get<1>(key), std::get<2>(key)};
    SCOPED_TRACE(tilePath(t, ""));
    const glm::dvec3 h = m.horizon_point;
    EXPECT_NEAR(glm::dot(glm::normalize(h), glm::normalize(m.sphere_center)), 1.0, 1e-12) << "on the tile's axis";
    if (t.level == 0) {
      EXPECT_GE(glm::length(h), 999.0) << "root tiles: a distant point (no finite one exists)";
      continue;
    }
    ASSERT_GT(glm::length(h), 1.0);
    double tightest = 1e9;
    for (std::size_t k = 0; k < m.u.size(); ++k) {
      const glm::dvec3 p = vertexPosition(t, m, k, r) / r;
      EXPECT_TRUE(insideHorizonCone(p, h, 1e-7)) << "vertex " << k;
      EXPECT_GE(glm::dot(glm::length(p) < 1.0 ? glm::normalize(p) : p, h), 1.0 - 1e-9) << "below the horizon plane";
      tightest = std::min(tightest, std::abs(glm::dot(glm::normalize(p), glm::normalize(h)) - 1.0 / glm::length(h)));
    }
    EXPECT_LT(tightest, 0.05) << "the point is far from the tightest one";
  }
}

// Edge e of a tile and the opposite edge of its neighbour: same vertices, same heights.
void expectSharedEdge(const DecodedMesh& a, int edgeA, const DecodedMesh& b, int edgeB) {
  const auto& ea = a.edges[std::size_t(edgeA)];
  const auto& eb = b.edges[std::size_t(edgeB)];
  ASSERT_EQ(ea.size(), std::size_t(kMeshCells + 1)) << "every grid vertex of the edge is kept";
  ASSERT_EQ(ea.size(), eb.size());
  const bool alongU = edgeA == 1 || edgeA == 3;  // south/north edges run along u
  for (std::size_t k = 0; k < ea.size(); ++k) {
    const std::size_t i = ea[k], j = eb[k];
    EXPECT_EQ(alongU ? a.u[i] : a.v[i], alongU ? b.u[j] : b.v[j]) << "vertex " << k;
    EXPECT_NEAR(a.height_m(i), b.height_m(j), 0.5 * (a.heightStep_m() + b.heightStep_m()) + 1e-6) << "vertex " << k;
    EXPECT_NEAR(glm::dot(a.normals[i], b.normals[j]), 1.0, 1e-12) << "vertex " << k;
  }
}

TEST_F(BakeTilesTest, NeighboursShareTheirEdgeVertices) {
  const auto& tiles = baked().tiles;
  int pairs = 0;
  for (const auto& [key, m] : tiles) {
    const auto [level, x, y] = key;
    if (auto east = tiles.find({level, (x + 1) % tilesAcross(level), y}); east != tiles.end()) {
      expectSharedEdge(m, 2, east->second, 0);
      ++pairs;
    }
    if (auto north = tiles.find({level, x, y + 1}); north != tiles.end()) {
      expectSharedEdge(m, 3, north->second, 1);
      ++pairs;
    }
  }
  EXPECT_GE(pairs, 8);
}

TEST_F(BakeTilesTest, HeightsMatchTheCpuModelWithinTheLevelsError) {
  const ElevationModel& model = earthlikeModel();
  double worstKept = 0.0, worstRemovedFraction = 0.0;
  for (const auto& [key, m] : baked().tiles) {
    const TileId t{std::get<0>(key), std::get<1>(key), std::get<2>(key)};
    SCOPED_TRACE(tilePath(t, ""));
    auto truth = [&](int i, int j) {
      const LonLat p = tileSampleLonLat(t, kMeshCells, i, j);
      return model.elevation_m(directionFromLatLon(p.lat_deg, p.lon_deg));
    };
    std::vector<bool> kept(std::size_t(kMeshCells + 1) * (kMeshCells + 1), false);
    for (std::size_t k = 0; k < m.u.size(); ++k) {
      const glm::ivec2 g = gridIndex(m, k);
      kept[std::size_t(g.y) * (kMeshCells + 1) + std::size_t(g.x)] = true;
      const double d = std::abs(m.height_m(k) - truth(g.x, g.y));
      worstKept = std::max(worstKept, d);
      EXPECT_LE(d, 0.5 * m.heightStep_m() + 1e-6) << "vertex " << k;
    }
    const double error_m = levelGeometricError_m(earthlike().radius_m, t.level);
    const std::vector<double> mesh = meshHeightsOnGrid(m, kMeshCells);  // the read-back's interpolation
    for (int j = 0; j <= kMeshCells; j += 3) {                          // every third row
      for (int i = 0; i <= kMeshCells; ++i) {
        if (kept[std::size_t(j) * (kMeshCells + 1) + std::size_t(i)]) continue;
        const double h = mesh[std::size_t(j) * (kMeshCells + 1) + std::size_t(i)];
        ASSERT_FALSE(std::isnan(h)) << "grid sample " << i << "," << j << " outside every triangle";
        const double d = std::abs(h - truth(i, j));
        worstRemovedFraction = std::max(worstRemovedFraction, d / error_m);
        EXPECT_LE(d, error_m + m.heightStep_m()) << "grid sample " << i << "," << j;
      }
    }
  }
  std::printf("worst kept vertex %.2e m; worst removed sample %.2f of the level's error\n", worstKept,
              worstRemovedFraction);
}

TEST_F(BakeTilesTest, ShardsGiveByteIdenticalTiles) {
  const Baked& one = baked();
  TempDir sharded("bake_tiles_sharded");
  GpuHeightSampler heights(device(), earthlikeModel());
  for (std::uint32_t k : {1u, 0u}) {
    BakeSettings s = settingsFor(BakeFormat::QuantizedMesh, sharded.str());
    s.shard = {k, 2};
    s.threads = 1;
    auto summary = runBake(earthlike(), heights, s, writeFile);
    ASSERT_TRUE(summary.ok()) << summary.error().format();
  }
  std::size_t compared = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(one.dir.str())) {
    if (!entry.is_regular_file()) continue;
    const auto rel = std::filesystem::relative(entry.path(), one.dir.str());
    EXPECT_EQ(readFileBytes(entry.path()), readFileBytes(sharded / rel.string())) << rel;
    ++compared;
  }
  EXPECT_EQ(compared, one.tiles.size() + 3) << "tiles, bake.json, layer.json and the empty .bake.lock";
}

TEST_F(BakeTilesTest, CogTilesReadBackThroughGdal) {
  TempDir dir("bake_tiles_cog");
  GpuHeightSampler heights(device(), earthlikeModel());
  BakeSettings s = settingsFor(BakeFormat::Cog, dir.str());
  s.levels = {2, 3};
  auto summary = runBake(earthlike(), heights, s, writeFile);
  ASSERT_TRUE(summary.ok()) << summary.error().format();
  const BakePlan plan(s.levels, s.region);
  for (std::uint64_t i = 0; i < plan.tileCount(); ++i) {
    const TileId t = plan.tileAt(i);
    SCOPED_TRACE(tilePath(t, ".tif"));
    GDALDatasetH ds = GDALOpen((dir / tilePath(t, ".tif")).c_str(), GA_ReadOnly);
    ASSERT_NE(ds, nullptr);
    const char* layout = GDALGetMetadataItem(ds, "LAYOUT", "IMAGE_STRUCTURE");
    EXPECT_STREQ(layout, "COG");
    EXPECT_EQ(GDALGetRasterXSize(ds), kCogPixels);
    double gt[6];
    ASSERT_EQ(GDALGetGeoTransform(ds, gt), CE_None);
    EXPECT_EQ(gt[0], tileRect(t).west_deg);
    EXPECT_EQ(gt[3], tileRect(t).north_deg);
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    EXPECT_EQ(GDALGetOverviewCount(band), 1);
    std::vector<float> pixels(std::size_t(kCogPixels) * kCogPixels);
    ASSERT_EQ(GDALRasterIO(band, GF_Read, 0, 0, kCogPixels, kCogPixels, pixels.data(), kCogPixels, kCogPixels,
                           GDT_Float32, 0, 0),
              CE_None);
    GDALClose(ds);
    std::vector<glm::dvec3> directions;
    appendCogDirections(t, directions);
    for (std::size_t k = 0; k < pixels.size(); k += 97) {
      const double h = earthlikeModel().elevation_m(directions[k]);
      EXPECT_NEAR(pixels[k], h, std::abs(h) * 1e-7 + 1e-6) << "pixel " << k;
    }
  }
}

}  // namespace
}  // namespace globe::testing
