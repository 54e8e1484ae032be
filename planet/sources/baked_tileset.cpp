#include "planet/sources/baked_tileset.h"

#include "planet/core/input_file.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace globe {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxManifestBytes = std::size_t(4) << 20;

Result<nlohmann::json> readJson(const std::string& path, const char* what) {
  auto text = readInputFile(path, what, kMaxManifestBytes);
  if (!text) return text.error();
  nlohmann::json json = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded() || !json.is_object())
    return Error::inFile(path, std::string("not a JSON object (") + what + ")");
  return json;
}

// bake.json as globe bake writes it (engine/bake/bake_manifest.cpp).
Result<BakedTileset> fromBakeJson(const std::string& dir, const std::string& path) {
  auto json = readJson(path, "bake manifest");
  if (!json) return json.error();
  const nlohmann::json& j = *json;
  auto bad = [&](const char* key) { return Error::inFileField(path, key, "missing or malformed"); };
  if (!j.contains("format") || !j["format"].is_string()) return bad("format");
  auto format = parseBakeFormat(j["format"].get<std::string>(), "format");
  if (!format) return Error::inFileField(path, "format", format.error().message);
  const auto& levels = j.value("levels", nlohmann::json());
  const auto& region = j.value("region", nlohmann::json());
  if (!levels.is_array() || levels.size() != 2 || !levels[0].is_number_integer() || !levels[1].is_number_integer())
    return bad("levels");
  if (!region.is_array() || region.size() != 4) return bad("region");
  for (const auto& v : region)
    if (!v.is_number()) return bad("region");
  const int last = levels[1].get<int>();
  // [10, 0] was accepted: the levels must be in order, like --levels A..B.
  if (levels[0].get<int>() < 0 || levels[0].get<int>() > last || last > kMaxTileLevel) return bad("levels");
  const GeoRect rect{region[0].get<double>(), region[1].get<double>(), region[2].get<double>(),
                     region[3].get<double>()};
  if (!(rect.west_deg < rect.east_deg && rect.south_deg < rect.north_deg)) return bad("region");
  BakedTileset t;
  t.directory = dir;
  t.format = *format;
  t.finest = BakePlan(LevelRange{last, last}, rect).ranges().back();
  t.radius_m = j.value("radius_m", 0.0);
  t.name = j.value("planet", std::string());
  if (!(t.radius_m > 0.0)) return bad("radius_m");
  return t;
}

// The finest level of layer.json's "available" with any range, and the rectangle around its ranges.
Result<TileRange> finestAvailable(const nlohmann::json& available, const std::string& path) {
  if (!available.is_array() || available.empty())
    return Error::inFileField(path, "available", "missing or empty (no tile is available)");
  for (int level = int(available.size()) - 1; level >= 0 && level <= kMaxTileLevel; --level) {
    const auto& ranges = available[std::size_t(level)];
    if (!ranges.is_array() || ranges.empty()) continue;
    TileRange r{level, UINT32_MAX, UINT32_MAX, 0, 0};
    for (const auto& range : ranges) {
      for (const char* key : {"startX", "startY", "endX", "endY"}) {
        if (!range.is_object() || !range.contains(key) || !range[key].is_number_unsigned())
          return Error::inFileField(path, fmt::format("available[{}]", level), "malformed range");
      }
      r.x0 = std::min(r.x0, range["startX"].get<std::uint32_t>());
      r.y0 = std::min(r.y0, range["startY"].get<std::uint32_t>());
      r.x1 = std::max(r.x1, range["endX"].get<std::uint32_t>());
      r.y1 = std::max(r.y1, range["endY"].get<std::uint32_t>());
    }
    if (r.x0 > r.x1 || r.y0 > r.y1 || r.x1 >= tilesAcross(level) || r.y1 >= tilesDown(level))
      return Error::inFileField(path, fmt::format("available[{}]", level), "range outside the level's tiles");
    return r;
  }
  return Error::inFileField(path, "available", "no level lists a tile");
}

// layer.json: TileJSON of a quantized-mesh tileset in the TMS geographic tiling, tiles at
// {z}/{x}/{y}.terrain.
Status checkLayerJson(const std::string& path, BakedTileset& t, bool fromBakeJson) {
  auto json = readJson(path, "tileset description (layer.json)");
  if (!json) return json.error();
  const nlohmann::json& j = *json;
  if (j.value("format", std::string()) != "quantized-mesh-1.0")
    return Error::inFileField(path, "format", "is not \"quantized-mesh-1.0\"");
  if (j.value("scheme", std::string("tms")) != "tms") return Error::inFileField(path, "scheme", "is not \"tms\"");
  if (j.value("projection", std::string("EPSG:4326")) != "EPSG:4326")
    return Error::inFileField(path, "projection", "is not \"EPSG:4326\" (the geographic tiling)");
  const auto& tiles = j.value("tiles", nlohmann::json());
  if (!tiles.is_array() || tiles.empty() || !tiles[0].is_string() ||
      tiles[0].get<std::string>().rfind("{z}/{x}/{y}.terrain", 0) != 0)
    return Error::inFileField(path, "tiles", "is not [\"{z}/{x}/{y}.terrain\"]");
  if (fromBakeJson) return Ok{};
  auto finest = finestAvailable(j.value("available", nlohmann::json()), path);
  if (!finest) return finest.error();
  t.finest = *finest;
  t.radius_m = j.value("globe_radius_m", 0.0);  // another tiler's tileset: WGS 84
  t.name = j.value("name", std::string("tileset"));
  return Ok{};
}

}  // namespace

std::string BakedTileset::tilePathOf(std::uint32_t x, std::uint32_t y) const {
  return (fs::path(directory) / tilePath(TileId{finest.level, x, y}, tile_extension.c_str())).string();
}

bool looksLikeBakedTileset(const std::string& directory) {
  std::error_code ec;
  return fs::is_directory(directory, ec) &&
         (fs::exists(fs::path(directory) / "bake.json", ec) || fs::exists(fs::path(directory) / "layer.json", ec));
}

Result<BakedTileset> inspectBakedTileset(const std::string& directory, std::optional<BakeFormat> expected) {
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return Error::inFile(directory, "no such directory");
  const std::string bakeJson = (fs::path(directory) / "bake.json").string();
  const std::string layerJson = (fs::path(directory) / "layer.json").string();
  const bool haveBake = fs::exists(bakeJson, ec), haveLayer = fs::exists(layerJson, ec);
  BakedTileset t;
  if (haveBake) {
    auto baked = fromBakeJson(directory, bakeJson);
    if (!baked) return baked.error();
    t = *baked;
  } else if (haveLayer && expected.value_or(BakeFormat::QuantizedMesh) == BakeFormat::QuantizedMesh) {
    t.directory = directory;
  } else {
    return Error::inFile(directory, expected == BakeFormat::Cog
                                        ? "holds no bake.json (a COG set is read as globe bake wrote it)"
                                        : "holds no bake.json or layer.json (not a baked tileset)");
  }
  if (expected && *expected != t.format)
    return Error::inFile(
        haveBake ? bakeJson : layerJson,
        fmt::format("holds a {} tileset, not {}", bakeFormatName(t.format), bakeFormatName(*expected)));
  if (t.format == BakeFormat::QuantizedMesh) {
    if (!haveLayer) return Error::inFile(layerJson, "no such file (a quantized-mesh tileset needs its layer.json)");
    if (Status s = checkLayerJson(layerJson, t, haveBake); !s) return s.error();
  }
  t.tile_extension = t.format == BakeFormat::Cog ? ".tif" : ".terrain";
  return t;
}

}  // namespace globe
