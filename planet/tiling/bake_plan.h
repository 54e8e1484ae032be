#pragma once
// What a bake covers and how it splits: the tiles of levels A..B that overlap a region, in one
// fixed order (level, then y, then x), dealt out round-robin to N shards so that shard K of N is a
// pure function of the plan. Shards share nothing but the output directory; each tile is one file.
#include "planet/core/error.h"
#include "planet/tiling/geographic_tiling.h"

#include <cstdint>
#include <string>
#include <vector>

namespace globe {

enum class BakeFormat { QuantizedMesh, Cog };

struct LevelRange {
  int first = 0;
  int last = 0;
};

struct Shard {
  std::uint32_t index = 0;  // K, 0-based (a Kubernetes completion index, a Slurm array task id)
  std::uint32_t count = 1;  // N
};

// "quantized-mesh" | "cog".
Result<BakeFormat> parseBakeFormat(const std::string& text, const std::string& field);
const char* bakeFormatName(BakeFormat format);
// "A..B" with 0 <= A <= B <= kMaxTileLevel (or "A": one level).
Result<LevelRange> parseLevelRange(const std::string& text, const std::string& field);
// "W,S,E,N" in degrees, -180 <= W < E <= 180, -90 <= S < N <= 90.
Result<GeoRect> parseRegion(const std::string& text, const std::string& field);
// "K/N" with 0 <= K < N <= 1000000.
Result<Shard> parseShard(const std::string& text, const std::string& field);

class BakePlan {
 public:
  // Level 0 is always whole (both root tiles, whatever the region): a client needs both roots
  // before it asks for anything finer.
  BakePlan(LevelRange levels, const GeoRect& region);

  const std::vector<TileRange>& ranges() const { return ranges_; }  // one per level, first..last
  std::uint64_t tileCount() const { return total_; }
  // A plan reaches 2^49 tiles (levels 0..24, the whole planet), so it is never listed: a shard's
  // tiles are computed one at a time. The tiles of `shard`: how many, and the j-th in plan order
  // (j < tileCountOf(shard)).
  std::uint64_t tileCountOf(const Shard& shard) const;
  TileId tileOf(const Shard& shard, std::uint64_t j) const;
  // The tile at `index` (< tileCount()) in plan order.
  TileId tileAt(std::uint64_t index) const;

 private:
  std::vector<TileRange> ranges_;
  std::uint64_t total_ = 0;
};

// "{level}/{x}/{y}" + extension (".terrain", ".tif"): the tile's path inside the output directory.
std::string tilePath(const TileId& tile, const char* extension);

}  // namespace globe
