#pragma once
// Reading a planet file's [[vectors]] (planet/model/planet_file.cpp calls it), key by key like
// [[sources]]: each problem is one Error at the key's line and column. The vector file is read and
// indexed once here (exists, the reader reads it, the layer and colour_by attribute exist, every feature
// reprojects inside the world, within the limits), so a planet that loads has layers that open.
#include "planet/core/planet_toml_reader.h"
#include "planet/vectors/vector_layer.h"

#include <optional>
#include <string>
#include <vector>

namespace globe {

// `planetDirectory`: the planet file's folder, against which relative paths resolve ("" = the
// current directory, for text without a file). At most kMaxVectorLayers tables.
void readVectors(PlanetTomlReader& r, const toml::node& node, const std::string& planetDirectory,
                 std::vector<VectorLayer>& layers);

// The [[vectors]] tables of `layers` as readVectors reads them back (colours as linear [r, g, b]).
std::string formatVectorsToml(const std::vector<VectorLayer>& layers);

// A colour as [[vectors]] writes it: "#rrggbb" (sRGB, returned linear) or [r, g, b] (linear, each
// in [0, 1]). Problems are reported at `field`.
std::optional<glm::vec3> readVectorColour(PlanetTomlReader& r, const toml::node& node, const std::string& field);

}  // namespace globe
