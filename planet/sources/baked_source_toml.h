#pragma once
// The [[sources]] keys of a baked tileset (docs/planet-files.md#sources): `path` naming a directory
// written by `globe bake` (or a quantized-mesh tileset), and `format` ("raster", the default for a
// file; "quantized-mesh" or "cog", detected from the directory when absent). Checked after the
// table's other keys (source_toml.cpp), since `format` may follow `path`.
#include "planet/core/planet_toml_reader.h"
#include "planet/sources/source_description.h"

#include <string>

namespace globe {

struct BakedSourceKeys {
  const toml::node* path = nullptr;
  const toml::node* format = nullptr;
  bool amplifyGiven = false;
};

// Validates `format` against what `source.path` is (a file, a tileset of that format) and opens a
// tileset once (every tile decoded), each problem one error at its key. A tileset's `amplify`
// defaults to false: it reads back the baked heights.
void checkBakedSource(PlanetTomlReader& r, const BakedSourceKeys& keys, const std::string& prefix,
                      ElevationSource& source);

}  // namespace globe
