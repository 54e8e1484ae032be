#include "planet/vectors/vector_toml.h"

#include "planet/core/srgb.h"
#include "planet/vectors/indexed_vector_layer.h"

#include <fmt/format.h>

#include <filesystem>
#include <iterator>
#include <map>

namespace globe {
namespace {

constexpr std::string_view kVectorKeys[] = {"path",         "layer",         "fill",      "fill_opacity",
                                            "line",         "line_opacity",  "width_m",   "width_px",
                                            "point_size_m", "point_size_px", "colour_by", "colours"};
constexpr double kMaxWidth_m = 1.0e6;
constexpr double kMaxWidth_px = 100.0;

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "#rrggbb" -> linear RGB.
std::optional<glm::vec3> parseHexColour(const std::string& text) {
  if (text.size() != 7 || text[0] != '#') return std::nullopt;
  glm::vec3 c(0.0f);
  for (int i = 0; i < 3; ++i) {
    const int high = hexDigit(text[std::size_t(1 + 2 * i)]), low = hexDigit(text[std::size_t(2 + 2 * i)]);
    if (high < 0 || low < 0) return std::nullopt;
    c[i] = static_cast<float>(srgbDecode((high * 16 + low) / 255.0));
  }
  return c;
}

// The keys whose values the file check depends on, or that are checked together.
struct VectorKeys {
  const toml::node* path = nullptr;
  const toml::node* layer = nullptr;
  const toml::node* colour_by = nullptr;
  const toml::node* colours = nullptr;
  const toml::node* width_m = nullptr;
  const toml::node* width_px = nullptr;
  const toml::node* point_size_m = nullptr;
  const toml::node* point_size_px = nullptr;
  bool path_ok = false;
};

void readPath(PlanetTomlReader& r, const toml::node& node, const std::string& field, const std::string& directory,
              VectorLayer& layer, VectorKeys& keys) {
  auto path = r.path(node, field, directory);
  if (!path) return;
  layer.path = *path;
  std::error_code ec;
  if (!std::filesystem::exists(layer.path, ec)) {
    r.fail(node.source(), field, fmt::format("no such file '{}'", layer.path));
    return;
  }
  keys.path_ok = true;  // opened once the whole table is read (layer, colour_by)
}

void readRanged(PlanetTomlReader& r, const toml::node& node, const std::string& field, double low, double high,
                bool openLow, double& out) {
  auto v = r.number(node, field);
  if (!v) return;
  if (*v < low || *v > high || (openLow && *v == low)) {
    r.fail(node.source(), field, fmt::format("must be in {}{}, {}]", openLow ? "(" : "[", low, high));
  } else {
    out = *v;
  }
}

void readOpacity(PlanetTomlReader& r, const toml::node& node, const std::string& field, float& out) {
  double v = out;
  readRanged(r, node, field, 0.0, 1.0, false, v);
  out = static_cast<float>(v);
}

void readColours(PlanetTomlReader& r, const toml::node& node, const std::string& field, VectorLayer& layer) {
  const toml::table* t = r.table(node, field, "attribute value = colour");
  if (t == nullptr) return;
  if (t->size() > kMaxVectorColours) {
    r.fail(node.source(), field, fmt::format("at most {} colours", kMaxVectorColours));
    return;
  }
  for (auto&& [key, value] : *t) {
    const std::string k(key.str());
    if (auto c = readVectorColour(r, value, field + "." + k)) layer.colours[k] = *c;
  }
}

void readStyleKey(PlanetTomlReader& r, const std::string& k, const toml::node& node, const std::string& field,
                  VectorLayer& layer) {
  if (k == "fill") {
    layer.fill = readVectorColour(r, node, field);
  } else if (k == "line") {
    layer.line = readVectorColour(r, node, field);
  } else if (k == "fill_opacity") {
    readOpacity(r, node, field, layer.fill_opacity);
  } else if (k == "line_opacity") {
    readOpacity(r, node, field, layer.line_opacity);
  } else if (k == "width_m") {
    readRanged(r, node, field, 0.0, kMaxWidth_m, true, layer.width_m);
  } else if (k == "width_px") {
    readRanged(r, node, field, 0.0, kMaxWidth_px, true, layer.width_px);
  } else if (k == "point_size_m") {
    readRanged(r, node, field, 0.0, kMaxWidth_m, true, layer.point_size_m);
  } else if (k == "point_size_px") {
    readRanged(r, node, field, 0.0, kMaxWidth_px, true, layer.point_size_px);
  } else if (k == "colours") {
    readColours(r, node, field, layer);
  }
}

void readVectorKey(PlanetTomlReader& r, const std::string& k, const toml::node& node, const std::string& field,
                   const std::string& directory, VectorLayer& layer, VectorKeys& keys) {
  if (k == "path") {
    keys.path = &node;
    readPath(r, node, field, directory, layer, keys);
  } else if (k == "layer" || k == "colour_by") {
    (k == "layer" ? keys.layer : keys.colour_by) = &node;
    auto v = r.string(node, field);
    if (v && v->empty()) r.fail(node.source(), field, "must not be empty");
    if (v && !v->empty()) (k == "layer" ? layer.layer : layer.colour_by) = *v;
  } else {
    if (k == "colours") keys.colours = &node;
    if (k == "width_m") keys.width_m = &node;
    if (k == "width_px") keys.width_px = &node;
    if (k == "point_size_m") keys.point_size_m = &node;
    if (k == "point_size_px") keys.point_size_px = &node;
    readStyleKey(r, k, node, field, layer);
  }
}

// The rules between keys: one width unit, colour_by with colours.
void checkTogether(PlanetTomlReader& r, const toml::table& t, const std::string& prefix, VectorLayer& layer,
                   const VectorKeys& keys) {
  if (keys.path == nullptr) r.fail(t.source(), prefix + "path", "missing (required)");
  if (keys.width_m != nullptr && keys.width_px != nullptr)
    r.fail(keys.width_px->source(), prefix + "width_px", "give width_m or width_px, not both");
  else if (keys.width_m != nullptr)
    layer.width_px = 0.0;
  if (keys.point_size_m != nullptr && keys.point_size_px != nullptr)
    r.fail(keys.point_size_px->source(), prefix + "point_size_px", "give point_size_m or point_size_px, not both");
  else if (keys.point_size_m != nullptr)
    layer.point_size_px = 0.0;
  if (keys.colours != nullptr && keys.colour_by == nullptr)
    r.fail(keys.colours->source(), prefix + "colours", "needs colour_by (the attribute whose value picks the colour)");
  if (keys.colour_by != nullptr && keys.colours == nullptr)
    r.fail(keys.colour_by->source(), prefix + "colour_by", "needs a colours table (attribute value = colour)");
}

// Reads and indexes the layer as the overlay will (which then shares it); a failure lands on the
// key it is about.
void checkFile(PlanetTomlReader& r, const std::string& prefix, const VectorLayer& layer, const VectorKeys& keys) {
  Result<std::shared_ptr<const IndexedVectorLayer>> opened = openIndexedVectorLayer(layer);
  if (opened) return;
  const Error& e = opened.error();
  const toml::node* at = keys.path;
  if (e.field == "layer" && keys.layer != nullptr) at = keys.layer;
  if (e.field == "colour_by" && keys.colour_by != nullptr) at = keys.colour_by;
  const std::string key = at == keys.path ? "path" : e.field;
  r.fail(at->source(), prefix + key, fmt::format("'{}' {}", layer.path, e.message));
}

void readVector(PlanetTomlReader& r, const toml::table& t, std::size_t index, const std::string& directory,
                std::vector<VectorLayer>& layers) {
  const std::string prefix = fmt::format("vectors[{}].", index);
  VectorLayer layer;
  VectorKeys keys;
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    if (!isKnownKey(k, kVectorKeys)) {
      r.fail(key.source(), prefix + k, unknownKeyMessage(k, kVectorKeys));
      continue;
    }
    readVectorKey(r, k, node, prefix + k, directory, layer, keys);
  }
  checkTogether(r, t, prefix, layer, keys);
  if (keys.path_ok) checkFile(r, prefix, layer, keys);
  layers.push_back(std::move(layer));
}

}  // namespace

std::optional<glm::vec3> readVectorColour(PlanetTomlReader& r, const toml::node& node, const std::string& field) {
  if (node.is_string()) {
    auto text = r.string(node, field);
    std::optional<glm::vec3> c = text ? parseHexColour(*text) : std::nullopt;
    if (text && !c)
      r.fail(node.source(), field, fmt::format("expected \"#rrggbb\" (hexadecimal sRGB), got \"{}\"", *text));
    return c;
  }
  std::optional<glm::vec3> c = r.colour(node, field);
  if (c && (c->x < 0.0f || c->x > 1.0f || c->y < 0.0f || c->y > 1.0f || c->z < 0.0f || c->z > 1.0f)) {
    r.fail(node.source(), field, "components must be in [0, 1] (linear RGB)");
    return std::nullopt;
  }
  return c;
}

void readVectors(PlanetTomlReader& r, const toml::node& node, const std::string& planetDirectory,
                 std::vector<VectorLayer>& layers) {
  const toml::array* list = r.arrayOfTables(node, "vectors");
  if (list == nullptr) return;
  if (list->size() > kMaxVectorLayers)
    r.fail((*list)[kMaxVectorLayers].source(), "vectors", fmt::format("at most {} vector layers", kMaxVectorLayers));
  // Tables past the limit are not read: each would read a whole vector file.
  for (std::size_t i = 0; i < list->size() && i < kMaxVectorLayers; ++i)
    readVector(r, *(*list)[i].as_table(), i, planetDirectory, layers);
}

namespace {

std::string linear(const glm::vec3& c) { return fmt::format("[{}, {}, {}]", c.x, c.y, c.z); }

void formatVectorLayer(const VectorLayer& v, std::string& out) {
  auto line = std::back_inserter(out);
  fmt::format_to(line, "\n[[vectors]]\npath = {}\n", tomlQuoted(v.path));
  if (!v.layer.empty()) fmt::format_to(line, "layer = {}\n", tomlQuoted(v.layer));
  if (v.fill) fmt::format_to(line, "fill = {}\nfill_opacity = {}\n", linear(*v.fill), v.fill_opacity);
  if (v.line) fmt::format_to(line, "line = {}\n", linear(*v.line));
  fmt::format_to(line, "line_opacity = {}\n", v.line_opacity);
  if (v.width_m > 0.0) fmt::format_to(line, "width_m = {}\n", v.width_m);
  if (v.width_m <= 0.0) fmt::format_to(line, "width_px = {}\n", v.width_px);
  if (v.point_size_m > 0.0) fmt::format_to(line, "point_size_m = {}\n", v.point_size_m);
  if (v.point_size_m <= 0.0) fmt::format_to(line, "point_size_px = {}\n", v.point_size_px);
  if (v.colour_by.empty()) return;
  fmt::format_to(line, "colour_by = {}\ncolours = {{ ", tomlQuoted(v.colour_by));
  const char* separator = "";
  for (const auto& [value, colour] : v.colours) {
    fmt::format_to(line, "{}{} = {}", separator, tomlQuoted(value), linear(colour));
    separator = ", ";
  }
  out += " }\n";
}

}  // namespace

std::string formatVectorsToml(const std::vector<VectorLayer>& layers) {
  std::string out;
  for (const VectorLayer& v : layers) formatVectorLayer(v, out);
  return out;
}

}  // namespace globe
