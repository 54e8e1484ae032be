#pragma once
// Reading a planet file's [[sources]] (planet/model/planet_file.cpp calls it), key by key like
// every other table: each problem is one Error at the key's line and column. The raster itself is
// opened once here through the installed reader (exists, readable, georeferenced, CRS known), so
// a planet that loads has sources that open.
#include "planet/core/planet_toml_reader.h"
#include "planet/sources/source_description.h"

#include <string>
#include <vector>

namespace globe {

// `planetDirectory`: the planet file's folder, against which relative paths resolve ("" = the
// current directory, for text without a file).
void readSources(PlanetTomlReader& r, const toml::node& node, const std::string& planetDirectory,
                 std::vector<ElevationSource>& sources);

}  // namespace globe
