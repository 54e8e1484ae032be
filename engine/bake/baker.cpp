#include "engine/bake/baker.h"

#include "engine/bake/cog_tile.h"
#include "engine/bake/tile_mesh.h"
#include "planet/core/atomic_file.h"
#include "planet/core/input_file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>

namespace globe {

namespace fs = std::filesystem;

namespace {

const char* extensionOf(BakeFormat format) { return format == BakeFormat::Cog ? ".tif" : ".terrain"; }

// An exclusive lock on DIR/.bake.lock while a bake checks and writes the manifests: two bakes
// started together into one directory otherwise both found no bake.json and both wrote theirs, the
// second's hiding the first's tiles (issue 40). Released when the object goes (or the process dies).
class ManifestLock {
 public:
  explicit ManifestLock(const std::string& dir) : path_((fs::path(dir) / ".bake.lock").string()) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0) error_ = std::strerror(errno);
    if (fd_ < 0) error_ = std::strerror(errno);
  }
  ~ManifestLock() {
    if (fd_ >= 0) ::close(fd_);  // releases the flock
  }
  ManifestLock(const ManifestLock&) = delete;
  ManifestLock& operator=(const ManifestLock&) = delete;
  Status status() const {
    if (error_.empty()) return Ok{};
    return Error::inFile(path_, "cannot lock the bake's manifests: " + error_);
  }

 private:
  std::string path_;
  int fd_ = -1;
  std::string error_;
};

// bake.json must match the bake a directory already holds, or the resume would mix two bakes.
Status writeManifests(const BakeDescription& description, const BakePlan& plan, const std::string& dir) {
  const ManifestLock lock(dir);
  if (auto s = lock.status(); !s) return s;
  const std::string manifest = bakeJson(description);
  const std::string path = (fs::path(dir) / "bake.json").string();
  std::error_code ec;
  if (fs::exists(path, ec)) {
    auto existing = readInputFile(path, "bake manifest", 1 << 20);
    if (!existing) return existing.error();
    if (*existing != manifest) {
      return Error::inFile(path,
                           "the directory holds another bake (planet, format, levels or region differ); "
                           "use a new --out directory");
    }
  }
  std::vector<NamedContent> files{{"bake.json", manifest}};
  if (description.format == BakeFormat::QuantizedMesh) files.push_back({"layer.json", layerJson(description, plan)});
  return writeFilesAtomically(dir, files);
}

// Temporaries of this shard's unfinished tiles left by a killed run (AtomicFile names them
// ".NAME.tmpPID"); other shards' temporaries, possibly being written right now, are not touched.
void removeStaleTemporaries(const std::string& dir, const std::vector<TileId>& todo, const char* ext) {
  std::map<std::string, std::vector<std::string>> prefixes;  // column directory -> ".y.ext.tmp"
  for (const TileId& t : todo) {
    const fs::path p = fs::path(dir) / tilePath(t, ext);
    prefixes[p.parent_path().string()].push_back("." + p.filename().string() + ".tmp");
  }
  for (const auto& [column, names] : prefixes) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(column, ec)) {
      const std::string file = entry.path().filename().string();
      for (const std::string& prefix : names) {
        if (file.rfind(prefix, 0) == 0) fs::remove(entry.path(), ec);
      }
    }
  }
}

struct EncodedTile {
  std::string bytes;
  Status status = Ok{};
  TileMeshStats stats;
};

std::size_t samplesPerTile(BakeFormat format) {
  return format == BakeFormat::Cog ? std::size_t(kCogPixels) * kCogPixels
                                   : std::size_t(kMeshCells + 3) * std::size_t(kMeshCells + 3);
}

}  // namespace

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<EncodedTile> encodeBatch(const PlanetDescription& planet, HeightSampler& heights,
                                     const BakeSettings& settings, std::span<const TileId> batch,
                                     BakeSummary& summary) {
  auto start = std::chrono::steady_clock::now();
  std::vector<glm::dvec3> directions;
  for (const TileId& t : batch) {
    if (settings.format == BakeFormat::Cog) {
      appendCogDirections(t, directions);
    } else {
      appendGridDirections(t, kMeshCells, directions);
    }
  }
  const std::vector<double> h = heights.heights_m(directions);
  summary.heights_s += secondsSince(start);
  start = std::chrono::steady_clock::now();
  const std::size_t per = samplesPerTile(settings.format);
  std::vector<EncodedTile> out(batch.size());
  parallelFor(batch.size(), 1, settings.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const auto first = h.begin() + std::ptrdiff_t(k * per);
      std::vector<double> tileHeights(first, first + std::ptrdiff_t(per));
      if (settings.format == BakeFormat::Cog) {
        auto bytes = encodeCogTile(batch[k], tileHeights, planet.radius_m, planet.name, planet.flattening);
        if (bytes)
          out[k].bytes = std::move(*bytes);
        else
          out[k].status = bytes.error();
      } else {
        const TileGrid grid{batch[k], kMeshCells, std::move(tileHeights)};
        const double error_m = levelGeometricError_m(planet.radius_m, batch[k].level);
        out[k].bytes = encodeQuantizedMesh(buildTileMesh(grid, planetShape(planet), error_m, &out[k].stats));
      }
    }
  });
  summary.encode_s += secondsSince(start);
  return out;
}

// Encodes and writes `batch` (tiles not on disk yet): their directories, a killed run's
// temporaries of them removed, then the tiles, each atomically through `write`.
Status writeBatch(const PlanetDescription& planet, HeightSampler& heights, const BakeSettings& settings,
                  const std::vector<TileId>& batch, const TileWriter& write, BakeSummary& summary) {
  if (batch.empty()) return Ok{};
  const char* ext = extensionOf(settings.format);
  std::error_code ec;
  for (const TileId& t : batch) {
    fs::create_directories((fs::path(settings.out_dir) / tilePath(t, ext)).parent_path(), ec);
    if (ec) return Error::inFile(settings.out_dir, "cannot create tile directory: " + ec.message());
  }
  removeStaleTemporaries(settings.out_dir, batch, ext);
  std::vector<EncodedTile> encoded = encodeBatch(planet, heights, settings, batch, summary);
  const auto writeStart = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < batch.size(); ++k) {
    if (!encoded[k].status) return encoded[k].status.error();
    const std::string path = (fs::path(settings.out_dir) / tilePath(batch[k], ext)).string();
    if (auto s = write(path, encoded[k].bytes); !s) return s.error();
    ++summary.written;
    summary.bytes += encoded[k].bytes.size();
    summary.vertices += encoded[k].stats.vertices;
    summary.max_simplification_error_m =
        std::max(summary.max_simplification_error_m, encoded[k].stats.simplification_error_m);
  }
  summary.write_s += secondsSince(writeStart);
  return Ok{};
}

}  // namespace

Result<BakeSummary> runBake(const PlanetDescription& planet, HeightSampler& heights, const BakeSettings& settings,
                            const TileWriter& write, const ProgressFn& progress) {
  const BakePlan plan(settings.levels, settings.region);
  const ElevationModel model(planet);
  const BakeDescription description{settings.format,
                                    settings.levels,
                                    settings.region,
                                    planet.name,
                                    planet.radius_m,
                                    planet.flattening,
                                    elevationModelHash(model.params(), planet.sources)};
  std::error_code ec;
  fs::create_directories(settings.out_dir, ec);
  if (ec) return Error::inField("--out", "cannot create '" + settings.out_dir + "': " + ec.message());
  if (auto s = writeManifests(description, plan, settings.out_dir); !s) return s.error();

  BakeSummary summary;
  summary.plan_tiles = plan.tileCount();
  summary.shard_tiles = plan.tileCountOf(settings.shard);
  const char* ext = extensionOf(settings.format);
  const std::size_t batchTiles =
      std::max<std::size_t>(1, GpuHeightSampler::kBatchDirections / samplesPerTile(settings.format));
  std::vector<TileId> batch;
  // The shard is walked a batch of missing tiles at a time: memory stays one batch whatever the plan
  // (listing levels 0..14 of the planet first took 3 GB before a tile was written, issue 40).
  for (std::uint64_t j = 0; j < summary.shard_tiles;) {
    batch.clear();
    for (; j < summary.shard_tiles && batch.size() < batchTiles; ++j) {
      const TileId t = plan.tileOf(settings.shard, j);
      if (fs::exists(fs::path(settings.out_dir) / tilePath(t, ext), ec))
        ++summary.skipped;
      else
        batch.push_back(t);
    }
    if (auto s = writeBatch(planet, heights, settings, batch, write, summary); !s) return s.error();
    if (progress) progress(double(j) / double(summary.shard_tiles));
  }
  return summary;
}

}  // namespace globe
