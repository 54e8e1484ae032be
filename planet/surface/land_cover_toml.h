#pragma once
// Reading and writing a planet file's [climate] and [[land_cover]] (planet/model/planet_file.cpp
// and planet_file_writer.cpp call these), key by key like every other table: each problem is one
// Error at the key's line and column, and every value's position is remembered so that
// appendLandCoverErrors' findings ("land_cover[2].moisture") land on the key's line.
#include <string>
#include <vector>

#include "planet/core/planet_toml_reader.h"
#include "planet/surface/land_cover.h"

namespace globe {

// The [climate] table: keys are Climate's member names; keys not given keep their defaults.
void readClimate(PlanetTomlReader& r, const toml::node& node, Climate& climate);

// The [[land_cover]] classes, in file order (at most kMaxLandCoverClasses). `planetDirectory`: the
// planet file's folder, against which a relative `texture` resolves, as [[sources]] paths do ("" =
// the current directory, for text without a file).
void readLandCoverClasses(PlanetTomlReader& r, const toml::node& node, const std::string& planetDirectory,
                          std::vector<LandCoverClass>& classes);

// The rule between the two tables, once the whole file is read: [climate] needs [[land_cover]].
void checkLandCoverTables(PlanetTomlReader& r, const toml::table& root);

// [climate] and the [[land_cover]] tables as a planet file writes them (nothing when there is no
// land cover); read back they give the same LandCover. Unbounded range ends are written as +-1e30,
// a range unbounded at both ends (or slope_deg's [0, 90]) not at all.
std::string formatLandCoverToml(const LandCover& cover);

}  // namespace globe
