// The GDAL driver "GlobeBakedTileset" (planet/sources/baked_tileset.h): a directory of baked tiles opened as one
// raster, so that a baked planet is a source like any DEM (the mosaic, the RAM tile cache, the
// source I/O thread; docs/elevation-data.md, "Baked tilesets").
//   - COG: an in-memory VRT (GDALBuildVRT) over the finest level's .tif files, gaps no-data.
//   - quantized mesh: a raster whose pixel centres are a grid 4 x finer than the finest level's
//     65 x 65 vertex grid, 257 x 257 points per tile (shared edges once); a pixel is the tile's
//     triangles interpolated at that point, so a block of 256 x 256 pixels decodes one tile.
//     Missing tiles are no-data (NaN). Every tile is decoded once when the raster opens, for its
//     height range and so that a corrupt tile is an error naming the file before anything is drawn.
#include "planet/gdal/baked_tileset_driver.h"

#include "planet/core/input_file.h"
#include "planet/gdal/planet_crs.h"
#include "planet/sources/baked_tileset.h"
#include "planet/sources/tile_cache.h"
#include "planet/tiling/quantized_mesh_decoder.h"

#include <cpl_string.h>
#include <gdal_priv.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include <fmt/format.h>

#include <atomic>
#include <climits>
#include <cmath>
#include <filesystem>
#include <limits>
#include <mutex>

namespace globe {

namespace fs = std::filesystem;

namespace {

constexpr char kDriverName[] = "GlobeBakedTileset";
// Cells per tile side of the grid a quantized-mesh tile is read on: 4 x the bake's vertex grid
// (kMeshCells, engine/bake/tile_grid.h), so that the mosaic's bilinear interpolation between the
// raster's points stays close to the triangles (measured: docs/elevation-data.md).
constexpr int kReadCells = 256;
constexpr std::size_t kMaxTileBytes = std::size_t(64) << 20;

constexpr float kNoData = std::numeric_limits<float>::quiet_NaN();

// A tile decoded, or an Error naming its file; nullopt when the file does not exist.
Result<std::optional<DecodedMesh>> readMeshTile(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::optional<DecodedMesh>();
  auto bytes = readInputFile(path, "terrain tile", kMaxTileBytes);
  if (!bytes) return bytes.error();
  if (bytes->size() >= 2 && static_cast<unsigned char>((*bytes)[0]) == 0x1f &&
      static_cast<unsigned char>((*bytes)[1]) == 0x8b)
    return Error::inFile(path, "gzip-compressed tile (gunzip the tileset to read it back)");
  std::string why;
  std::optional<DecodedMesh> mesh = decodeQuantizedMesh(*bytes, &why);
  if (!mesh) return Error::inFile(path, "corrupt quantized-mesh tile: " + why);
  return mesh;
}

class QuantizedMeshDataset;

class QuantizedMeshBand final : public GDALRasterBand {
 public:
  explicit QuantizedMeshBand(QuantizedMeshDataset* dataset);
  CPLErr IReadBlock(int blockX, int blockY, void* image) override;
  double GetNoDataValue(int* success) override {
    if (success != nullptr) *success = TRUE;
    return double(kNoData);
  }
  CPLErr ComputeRasterMinMax(int approxOk, double* minMax) override;
};

class QuantizedMeshDataset final : public GDALDataset {
 public:
  // Decodes every tile (height range, validation); nullptr with a CPLError on failure.
  static GDALDataset* open(const BakedTileset& tileset);

  CPLErr GetGeoTransform(double* transform) override {
    std::copy(transform_, transform_ + 6, transform);
    return CE_None;
  }
  const OGRSpatialReference* GetSpatialRef() const override { return &srs_; }

  const BakedTileset& tileset() const { return tileset_; }
  double min_m = 0.0, max_m = 0.0;

 private:
  BakedTileset tileset_;
  double transform_[6] = {};
  OGRSpatialReference srs_;
};

QuantizedMeshBand::QuantizedMeshBand(QuantizedMeshDataset* dataset) {
  poDS = dataset;
  nBand = 1;
  eDataType = GDT_Float32;
  nBlockXSize = nBlockYSize = kSourceTilePixels;
  nRasterXSize = dataset->GetRasterXSize();
  nRasterYSize = dataset->GetRasterYSize();
}

CPLErr QuantizedMeshBand::ComputeRasterMinMax(int, double* minMax) {
  const auto* ds = static_cast<QuantizedMeshDataset*>(poDS);
  minMax[0] = ds->min_m;
  minMax[1] = ds->max_m;
  return CE_None;
}

// Pixel (i, j) (j from the north) lies on tile column i / kReadCells (the raster's last column on
// the last tile's east edge), at grid index i - kReadCells * column; rows likewise from the north.
CPLErr QuantizedMeshBand::IReadBlock(int blockX, int blockY, void* image) {
  const auto* ds = static_cast<QuantizedMeshDataset*>(poDS);
  const BakedTileset& t = ds->tileset();
  auto* out = static_cast<float*>(image);
  std::fill(out, out + std::size_t(nBlockXSize) * std::size_t(nBlockYSize), kNoData);
  const int i0 = blockX * nBlockXSize, j0 = blockY * nBlockYSize;
  const int i1 = std::min(i0 + nBlockXSize, nRasterXSize), j1 = std::min(j0 + nBlockYSize, nRasterYSize);
  const int columns = int(t.finest.x1 - t.finest.x0 + 1), rows = int(t.finest.y1 - t.finest.y0 + 1);
  // The raster's last row and column are the last tiles' edges (grid index kReadCells).
  for (int row = std::min(j0 / kReadCells, rows - 1); row <= std::min((j1 - 1) / kReadCells, rows - 1); ++row) {
    for (int column = std::min(i0 / kReadCells, columns - 1); column <= std::min((i1 - 1) / kReadCells, columns - 1);
         ++column) {
      const std::string path = t.tilePathOf(t.finest.x0 + std::uint32_t(column), t.finest.y1 - std::uint32_t(row));
      auto mesh = readMeshTile(path);
      if (!mesh) {
        CPLError(CE_Failure, CPLE_AppDefined, "%s", mesh.error().format().c_str());
        return CE_Failure;
      }
      if (!mesh->has_value()) continue;
      const std::vector<double> grid = meshHeightsOnGrid(**mesh, kReadCells);  // (i east, j north) from south-west
      const int lastI = column == columns - 1 ? kReadCells : kReadCells - 1;
      const int lastJ = row == rows - 1 ? kReadCells : kReadCells - 1;
      for (int gj = 0; gj <= lastJ; ++gj) {  // gj counts from the tile's north edge
        const int j = row * kReadCells + gj;
        if (j < j0 || j >= j1) continue;
        for (int gi = 0; gi <= lastI; ++gi) {
          const int i = column * kReadCells + gi;
          if (i < i0 || i >= i1) continue;
          const double h = grid[std::size_t(kReadCells - gj) * std::size_t(kReadCells + 1) + std::size_t(gi)];
          out[std::size_t(j - j0) * std::size_t(nBlockXSize) + std::size_t(i - i0)] = float(h);
        }
      }
    }
  }
  return CE_None;
}

GDALDataset* QuantizedMeshDataset::open(const BakedTileset& tileset) {
  const TileRange& r = tileset.finest;
  const std::uint64_t width = std::uint64_t(r.x1 - r.x0 + 1) * kReadCells + 1;
  const std::uint64_t height = std::uint64_t(r.y1 - r.y0 + 1) * kReadCells + 1;
  if (width > std::uint64_t(INT_MAX) || height > std::uint64_t(INT_MAX)) {
    CPLError(CE_Failure, CPLE_AppDefined, "%s: level %d over this region is too large to read as one raster",
             tileset.directory.c_str(), r.level);
    return nullptr;
  }
  auto ds = std::make_unique<QuantizedMeshDataset>();
  ds->tileset_ = tileset;
  ds->nRasterXSize = int(width);
  ds->nRasterYSize = int(height);
  const double step_deg = 180.0 / double(tilesDown(r.level)) / kReadCells;
  const GeoRect west = tileRect(TileId{r.level, r.x0, r.y1});
  const double transform[6] = {west.west_deg - 0.5 * step_deg,  step_deg, 0.0,
                               west.north_deg + 0.5 * step_deg, 0.0,      -step_deg};
  std::copy(transform, transform + 6, ds->transform_);
  if (tileset.radius_m > 0.0) {
    ds->srs_.importFromWkt(planetCrsWkt(tileset.radius_m, tileset.name).c_str());
  } else {
    ds->srs_.SetWellKnownGeogCS("WGS84");
  }
  ds->min_m = std::numeric_limits<double>::infinity();
  ds->max_m = -std::numeric_limits<double>::infinity();
  for (std::uint32_t y = r.y0; y <= r.y1; ++y) {
    for (std::uint32_t x = r.x0; x <= r.x1; ++x) {
      auto mesh = readMeshTile(tileset.tilePathOf(x, y));
      if (!mesh) {
        CPLError(CE_Failure, CPLE_AppDefined, "%s", mesh.error().format().c_str());
        return nullptr;
      }
      if (!mesh->has_value()) continue;
      for (std::size_t k = 0; k < (*mesh)->vertexCount(); ++k) {
        ds->min_m = std::min(ds->min_m, (*mesh)->height_m(k));
        ds->max_m = std::max(ds->max_m, (*mesh)->height_m(k));
      }
    }
  }
  if (!(ds->min_m <= ds->max_m)) {
    CPLError(CE_Failure, CPLE_AppDefined, "%s: no tile of level %d exists", tileset.directory.c_str(), r.level);
    return nullptr;
  }
  ds->SetBand(1, new QuantizedMeshBand(ds.get()));
  return ds.release();
}

// The finest level's COG tiles as one in-memory VRT; areas without a tile are no-data (NaN).
GDALDataset* openCogSet(const BakedTileset& t) {
  CPLStringList files;
  std::error_code ec;
  for (std::uint32_t y = t.finest.y0; y <= t.finest.y1; ++y)
    for (std::uint32_t x = t.finest.x0; x <= t.finest.x1; ++x)
      if (const std::string path = t.tilePathOf(x, y); fs::exists(path, ec)) files.AddString(path.c_str());
  if (files.empty()) {
    CPLError(CE_Failure, CPLE_AppDefined, "%s: no tile of level %d exists", t.directory.c_str(), t.finest.level);
    return nullptr;
  }
  static std::atomic<unsigned> serial{0};
  const std::string vrt = fmt::format("/vsimem/globe_baked_{}.vrt", serial++);
  CPLStringList args;
  for (const char* a : {"-strict", "-q", "-vrtnodata", "nan"}) args.AddString(a);
  GDALBuildVRTOptions* options = GDALBuildVRTOptionsNew(args.List(), nullptr);
  GDALDatasetH built = GDALBuildVRT(vrt.c_str(), files.size(), nullptr, files.List(), options, nullptr);
  GDALBuildVRTOptionsFree(options);
  if (built == nullptr) return nullptr;  // GDALBuildVRT said which tile (CPLError)
  GDALClose(built);                      // writes the VRT into /vsimem
  auto* ds = GDALDataset::Open(vrt.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY | GDAL_OF_INTERNAL);
  VSIUnlink(vrt.c_str());
  return ds;
}

int identify(GDALOpenInfo* info) { return info->bIsDirectory && looksLikeBakedTileset(info->pszFilename); }

GDALDataset* openTileset(GDALOpenInfo* info) {
  if (!identify(info) || info->eAccess != GA_ReadOnly) return nullptr;
  auto tileset = inspectBakedTileset(info->pszFilename);
  if (!tileset) {
    CPLError(CE_Failure, CPLE_AppDefined, "%s", tileset.error().format().c_str());
    return nullptr;
  }
  return tileset->format == BakeFormat::Cog ? openCogSet(*tileset) : QuantizedMeshDataset::open(*tileset);
}

}  // namespace

void registerBakedTilesetDriver() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (GDALGetDriverByName(kDriverName) != nullptr) return;
    auto* driver = new GDALDriver();  // owned by GDAL's driver manager
    driver->SetDescription(kDriverName);
    driver->SetMetadataItem(GDAL_DCAP_RASTER, "YES");
    driver->SetMetadataItem(GDAL_DMD_LONGNAME, "globe bake output (quantized-mesh or COG tiles) read back");
    driver->pfnIdentify = identify;
    driver->pfnOpen = openTileset;
    GetGDALDriverManager()->RegisterDriver(driver);
  });
}

}  // namespace globe
