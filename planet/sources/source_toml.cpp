#include "planet/sources/source_toml.h"

#include "planet/sources/baked_source_toml.h"
#include "planet/sources/raster_file.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

namespace globe {
namespace {

constexpr std::string_view kSourceKeys[] = {
    "path", "format", "nodata", "amplify", "priority", "vertical_scale", "vertical_offset_m", "blend_m"};
constexpr double kMaxVerticalScale = 1.0e6;
constexpr double kMaxVerticalOffset_m = 1.0e7;

void readPath(PlanetTomlReader& r, const toml::node& node, const std::string& field, const std::string& directory,
              ElevationSource& source) {
  auto path = r.path(node, field, directory);
  if (!path) return;
  source.path = *path;
  std::error_code ec;
  if (std::filesystem::is_directory(source.path, ec)) return;  // a baked tileset: checkBakedSource
  if (!std::filesystem::exists(source.path, ec)) {
    r.fail(node.source(), field, fmt::format("no such file '{}'", source.path));
    return;
  }
  // A FIFO or device is named as such (by the reader's input check), not "no such file".
  Result<std::unique_ptr<RasterFile>> raster = openRaster(source.path, 6371000.0);
  if (!raster) r.fail(node.source(), field, fmt::format("'{}' {}", source.path, raster.error().message));
}

void readNoData(PlanetTomlReader& r, const toml::node& node, const std::string& field, ElevationSource& source) {
  auto v = r.string(node, field);
  if (!v) return;
  if (*v == "fill") {
    source.nodata = NoDataMode::kFill;
  } else if (*v == "hole") {
    source.nodata = NoDataMode::kHole;
  } else {
    r.fail(node.source(), field, fmt::format("unknown nodata '{}' (fill, hole)", *v));
  }
}

void readSourceKey(PlanetTomlReader& r, const std::string& k, const toml::node& node, const std::string& field,
                   const std::string& directory, ElevationSource& source) {
  if (k == "path") {
    readPath(r, node, field, directory, source);
  } else if (k == "nodata") {
    readNoData(r, node, field, source);
  } else if (k == "amplify") {
    if (const auto* b = node.as_boolean()) {
      source.amplify = b->get();
    } else {
      r.fail(node.source(), field, fmt::format("expected a boolean, got {}", tomlTypeName(node.type())));
    }
  } else if (k == "priority") {
    if (auto v = r.integerIn(node, field, -1000000, 1000000)) source.priority = int(*v);
  } else if (k == "vertical_scale") {
    if (auto v = r.numberIn(node, field, -kMaxVerticalScale, kMaxVerticalScale)) source.vertical_scale = *v;
    if (source.vertical_scale == 0.0) r.fail(node.source(), field, "must not be 0");
  } else if (k == "vertical_offset_m") {
    if (auto v = r.numberIn(node, field, -kMaxVerticalOffset_m, kMaxVerticalOffset_m)) source.vertical_offset_m = *v;
  } else if (k == "blend_m") {
    if (auto v = r.numberIn(node, field, 0.0, 1.0e7)) source.blend_m = *v;
  }
}

void readSource(PlanetTomlReader& r, const toml::table& t, std::size_t index, const std::string& directory,
                std::vector<ElevationSource>& sources) {
  const std::string prefix = fmt::format("sources[{}].", index);
  ElevationSource source;
  BakedSourceKeys baked;
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    if (!isKnownKey(k, kSourceKeys)) {
      r.fail(key.source(), prefix + k, unknownKeyMessage(k, kSourceKeys));
      continue;
    }
    if (k == "path") baked.path = &node;
    if (k == "format") baked.format = &node;
    baked.amplifyGiven = baked.amplifyGiven || k == "amplify";
    if (k != "format") readSourceKey(r, k, node, prefix + k, directory, source);
  }
  if (baked.path == nullptr) r.fail(t.source(), prefix + "path", "missing (required)");
  if (baked.path != nullptr && !source.path.empty()) checkBakedSource(r, baked, prefix, source);
  sources.push_back(std::move(source));
}

}  // namespace

void readSources(PlanetTomlReader& r, const toml::node& node, const std::string& planetDirectory,
                 std::vector<ElevationSource>& sources) {
  const toml::array* list = r.arrayOfTables(node, "sources");
  if (list == nullptr) return;
  if (list->size() > std::size_t(kMaxElevationSources)) {
    r.fail((*list)[std::size_t(kMaxElevationSources)].source(), "sources",
           fmt::format("at most {} sources", kMaxElevationSources));
  }
  for (std::size_t i = 0; i < list->size(); ++i) readSource(r, *(*list)[i].as_table(), i, planetDirectory, sources);
}

}  // namespace globe
