#pragma once
// What a planet file's [[vectors]] table says about one vector layer draped on the terrain: which
// file and OGR layer, and how its polygons, lines and points are painted. Plain data, compared
// whole (a planet reloaded with the same layers keeps its overlay); reading the file is
// vector_features.h's job, painting it vector_overlay.h's.
#include <glm/vec3.hpp>

#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace globe {

struct VectorLayer {
  std::string path;   // as resolved: relative paths in a planet file are relative to the file's folder
  std::string layer;  // the OGR layer name; "" = the file's first layer

  std::optional<glm::vec3> fill;  // polygon fill, linear RGB; absent = polygons not filled
  float fill_opacity = 1.0f;      // [0, 1]
  // Lines and polygon outlines, linear RGB. Absent: polygons have no outline, and lines and points
  // are drawn in the fill colour, or white.
  std::optional<glm::vec3> line;
  float line_opacity = 1.0f;  // [0, 1]; points use it too

  // Exactly one of width_m / width_px is > 0: a width on the ground, or on the screen (pixels turn
  // into metres through the pixel size the overlay is asked at).
  double width_m = 0.0;
  double width_px = 2.0;
  // Marker diameter of points, likewise: one of point_size_m / point_size_px is > 0.
  double point_size_m = 0.0;
  double point_size_px = 8.0;

  // colour_by: an attribute whose value, looked up in `colours`, gives the colour of the feature's
  // fill, outline, line or marker. Features whose value is not in `colours` use fill / line.
  std::string colour_by;
  std::map<std::string, glm::vec3> colours;  // attribute value -> linear RGB

  bool operator==(const VectorLayer&) const = default;
};

// At most this many [[vectors]] tables in one planet (each is read whole into memory).
inline constexpr std::size_t kMaxVectorLayers = 16;
// Entries of one layer's colours table.
inline constexpr std::size_t kMaxVectorColours = 4096;

}  // namespace globe
