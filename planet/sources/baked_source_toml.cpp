#include "planet/sources/baked_source_toml.h"

#include "planet/sources/baked_tileset.h"
#include "planet/sources/raster_file.h"

#include <fmt/format.h>

#include <filesystem>
#include <optional>

namespace globe {

void checkBakedSource(PlanetTomlReader& r, const BakedSourceKeys& keys, const std::string& prefix,
                      ElevationSource& source) {
  std::optional<BakeFormat> expected;
  bool raster = false;
  if (keys.format != nullptr) {
    auto v = r.string(*keys.format, prefix + "format");
    if (!v) return;
    if (*v == "raster") {
      raster = true;
    } else if (auto f = parseBakeFormat(*v, prefix + "format"); f) {
      expected = *f;
    } else {
      r.fail(keys.format->source(), prefix + "format",
             fmt::format("unknown format '{}' (raster, quantized-mesh, cog)", escapeControlCharacters(*v)));
      return;
    }
  }
  std::error_code ec;
  const bool directory = std::filesystem::is_directory(source.path, ec);
  if (!directory) {
    if (expected) {
      r.fail(keys.path->source(), prefix + "path",
             fmt::format("'{}' is not a directory (a {} tileset is the directory globe bake --out wrote)", source.path,
                         bakeFormatName(*expected)));
    }
    return;
  }
  if (raster) {
    r.fail(keys.format->source(), prefix + "format",
           fmt::format("'{}' is a directory, not a raster file (quantized-mesh or cog)", source.path));
    return;
  }
  if (auto tileset = inspectBakedTileset(source.path, expected); !tileset) {
    r.fail(keys.path->source(), prefix + "path", tileset.error().format());
    return;
  }
  if (auto opened = openRaster(source.path, 6371000.0); !opened) {
    r.fail(keys.path->source(), prefix + "path", opened.error().message);
    return;
  }
  if (!keys.amplifyGiven) source.amplify = false;
}

}  // namespace globe
