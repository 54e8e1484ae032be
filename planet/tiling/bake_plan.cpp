#include "planet/tiling/bake_plan.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string_view>

namespace globe {

Result<BakeFormat> parseBakeFormat(const std::string& text, const std::string& field) {
  if (text == "quantized-mesh") return BakeFormat::QuantizedMesh;
  if (text == "cog") return BakeFormat::Cog;
  return Error::inField(field, "unknown format '" + escapeControlCharacters(text) + "' (quantized-mesh or cog)");
}

const char* bakeFormatName(BakeFormat format) { return format == BakeFormat::Cog ? "cog" : "quantized-mesh"; }

namespace {
// A level: decimal digits only (sscanf's %d took "1e1" as 1, "0x3" as 0 and "3.5" as 3).
std::optional<int> parseLevel(std::string_view text) {
  int v = 0;
  if (text.empty() || text.size() > 3 || text.find_first_not_of("0123456789") != std::string_view::npos) return {};
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}
}  // namespace

Result<LevelRange> parseLevelRange(const std::string& text, const std::string& field) {
  const std::string_view all(text);
  const auto dots = all.find("..");
  const auto first = parseLevel(all.substr(0, dots));
  const auto last = dots == std::string_view::npos ? first : parseLevel(all.substr(dots + 2));
  if (!first || !last)
    return Error::inField(field, "expected A..B (for example 0..5), got '" + escapeControlCharacters(text) + "'");
  const LevelRange r{*first, *last};
  if (r.first < 0 || r.last > kMaxTileLevel || r.first > r.last) {
    return Error::inField(field, "levels must satisfy 0 <= A <= B <= " + std::to_string(kMaxTileLevel) + ", got '" +
                                     escapeControlCharacters(text) + "'");
  }
  return r;
}

Result<GeoRect> parseRegion(const std::string& text, const std::string& field) {
  GeoRect r;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf,%lf%c", &r.west_deg, &r.south_deg, &r.east_deg, &r.north_deg, &extra) !=
      4) {
    return Error::inField(
        field, "expected W,S,E,N in degrees (for example 5,44,8,47), got '" + escapeControlCharacters(text) + "'");
  }
  for (double v : {r.west_deg, r.south_deg, r.east_deg, r.north_deg}) {
    if (!std::isfinite(v)) return Error::inField(field, "coordinates must be finite");
  }
  if (r.west_deg < -180.0 || r.east_deg > 180.0 || r.west_deg >= r.east_deg) {
    return Error::inField(field, "longitudes must satisfy -180 <= W < E <= 180");
  }
  if (r.south_deg < -90.0 || r.north_deg > 90.0 || r.south_deg >= r.north_deg) {
    return Error::inField(field, "latitudes must satisfy -90 <= S < N <= 90");
  }
  return r;
}

Result<Shard> parseShard(const std::string& text, const std::string& field) {
  long long k = 0, n = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lld/%lld%c", &k, &n, &extra) != 2 || text.find_first_of(" +") != std::string::npos) {
    return Error::inField(field, "expected K/N (shard K of N, K from 0), got '" + escapeControlCharacters(text) + "'");
  }
  if (n < 1 || n > 1000000 || k < 0 || k >= n) {
    return Error::inField(field,
                          "shard must satisfy 0 <= K < N <= 1000000, got '" + escapeControlCharacters(text) + "'");
  }
  return Shard{static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(n)};
}

BakePlan::BakePlan(LevelRange levels, const GeoRect& region) {
  for (int level = levels.first; level <= levels.last; ++level) {
    ranges_.push_back(tilesCovering(level, level == 0 ? GeoRect{} : region));
    total_ += ranges_.back().count();
  }
}

std::uint64_t BakePlan::tileCountOf(const Shard& shard) const {
  // Plan indices K, K + N, K + 2N, ... below the total.
  return total_ > shard.index ? (total_ - shard.index + shard.count - 1) / shard.count : 0;
}

TileId BakePlan::tileOf(const Shard& shard, std::uint64_t j) const { return tileAt(shard.index + j * shard.count); }

TileId BakePlan::tileAt(std::uint64_t index) const {
  for (const TileRange& r : ranges_) {
    if (index < r.count()) {
      const std::uint64_t width = std::uint64_t(r.x1 - r.x0) + 1;
      return {r.level, r.x0 + std::uint32_t(index % width), r.y0 + std::uint32_t(index / width)};
    }
    index -= r.count();
  }
  return {};  // past the plan: callers stay below tileCount()
}

std::string tilePath(const TileId& tile, const char* extension) {
  return std::to_string(tile.level) + "/" + std::to_string(tile.x) + "/" + std::to_string(tile.y) + extension;
}

}  // namespace globe
