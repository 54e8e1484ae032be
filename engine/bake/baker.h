#pragma once
// `globe bake`: one shard of a bake plan, written tile by tile into an output directory. Tiles that
// already exist are finished (each is written atomically) and skipped, so a killed shard resumes
// where it stopped; the bytes of a tile depend only on the planet and the tile, so reruns and other
// shard splits give identical files. Heights come in batches of many tiles from a HeightSampler.
#include "engine/bake/bake_manifest.h"
#include "engine/bake/height_sampler.h"
#include "planet/core/parallel_for.h"

#include <functional>
#include <string>
#include <string_view>

namespace globe {

struct BakeSettings {
  BakeFormat format = BakeFormat::QuantizedMesh;
  LevelRange levels;
  GeoRect region;
  Shard shard;
  std::string out_dir;   // created when missing
  unsigned threads = 1;  // CPU threads for meshes and encoding
};

struct BakeSummary {
  std::uint64_t plan_tiles = 0;   // the whole bake, every shard
  std::uint64_t shard_tiles = 0;  // this shard's
  std::uint64_t written = 0;
  std::uint64_t skipped = 0;  // already there
  double max_simplification_error_m = 0.0;
  std::uint64_t vertices = 0;  // over the written quantized-mesh tiles
  std::uint64_t bytes = 0;     // over the written tiles
  double heights_s = 0.0;      // wall-clock seconds sampling heights (GPU)
  double encode_s = 0.0;       // meshes / rasters and their encoding (CPU, `threads`)
  double write_s = 0.0;        // atomic writes (fsync per tile)
};

// Stores one finished tile (`path` inside the output directory); the command line wraps
// AtomicFile so an interrupt removes the temporary.
using TileWriter = std::function<Status(const std::string& path, std::string_view bytes)>;

// Tiles are written as they are finished; an Error stops the bake (finished tiles stay).
Result<BakeSummary> runBake(const PlanetDescription& planet, HeightSampler& heights, const BakeSettings& settings,
                            const TileWriter& write, const ProgressFn& progress = {});

}  // namespace globe
