#pragma once
// Reading a planet file's [[imagery]] (planet/model/planet_file.cpp calls it), key by key like
// [[sources]]: each problem is one Error at the key's line and column. The raster is opened here
// (exists, readable, georeferenced or given an extent, 8-bit bands), so a planet that loads has
// imagery that opens.
#include "planet/core/planet_toml_reader.h"
#include "planet/sources/imagery_source.h"

#include <string>
#include <vector>

namespace globe {

// `planetDirectory`: the planet file's folder, against which relative paths resolve.
void readImagery(PlanetTomlReader& r, const toml::node& node, const std::string& planetDirectory,
                 std::vector<ImagerySource>& imagery);

// The [[imagery]] tables of `imagery` as readImagery reads them back.
std::string formatImageryToml(const std::vector<ImagerySource>& imagery);

}  // namespace globe
