#include "planet/sources/imagery_toml.h"

#include "planet/sources/imagery_mosaic.h"

#include <fmt/format.h>

#include <filesystem>
#include <iterator>

namespace globe {
namespace {

constexpr std::string_view kImageryKeys[] = {"path", "extent", "priority", "opacity", "blend_m"};

void readPath(PlanetTomlReader& r, const toml::node& node, const std::string& field, const std::string& directory,
              ImagerySource& source) {
  auto path = r.path(node, field, directory);
  if (!path) return;
  source.path = *path;
  std::error_code ec;
  if (!std::filesystem::exists(source.path, ec))
    r.fail(node.source(), field, fmt::format("no such file '{}'", source.path));
}

// extent = [lon_min, lat_min, lon_max, lat_max], degrees (GDAL's -a_ullr order is not used: this is
// the order of a GeoJSON bbox).
void readExtent(PlanetTomlReader& r, const toml::node& node, const std::string& field, ImagerySource& source) {
  r.remember(field, node.source());
  const toml::array* a = node.as_array();
  if (a == nullptr || a->size() != 4) {
    r.fail(node.source(), field, "expected [lon_min, lat_min, lon_max, lat_max] in degrees");
    return;
  }
  double v[4] = {};
  for (std::size_t i = 0; i < 4; ++i) {
    auto n = r.number((*a)[i], field);
    if (!n) return;
    v[i] = *n;
  }
  r.remember(field, node.source());
  if (!(v[0] >= -540.0 && v[2] <= 540.0 && v[0] < v[2] && v[2] - v[0] <= 360.0))
    return r.fail(node.source(), field, "longitudes must satisfy lon_min < lon_max, at most 360 degrees apart");
  if (!(v[1] >= -90.0 && v[3] <= 90.0 && v[1] < v[3]))
    return r.fail(node.source(), field, "latitudes must satisfy -90 <= lat_min < lat_max <= 90");
  source.extent = GeographicExtent{v[0], v[1], v[2], v[3]};
}

void readKey(PlanetTomlReader& r, const std::string& k, const toml::node& node, const std::string& field,
             const std::string& directory, ImagerySource& source) {
  if (k == "path") {
    readPath(r, node, field, directory, source);
  } else if (k == "extent") {
    readExtent(r, node, field, source);
  } else if (k == "priority") {
    if (auto v = r.integerIn(node, field, -1000000, 1000000)) source.priority = int(*v);
  } else if (k == "opacity") {
    if (auto v = r.numberIn(node, field, 0.0, 1.0)) source.opacity = *v;
  } else if (k == "blend_m") {
    if (auto v = r.numberIn(node, field, 0.0, 1.0e7)) source.blend_m = *v;
  }
}

void readOne(PlanetTomlReader& r, const toml::table& t, std::size_t index, const std::string& directory,
             std::vector<ImagerySource>& imagery) {
  const std::string prefix = fmt::format("imagery[{}].", index);
  ImagerySource source;
  const toml::node* path = nullptr;
  const std::size_t before = r.errorCount();
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    if (!isKnownKey(k, kImageryKeys)) {
      r.fail(key.source(), prefix + k, unknownKeyMessage(k, kImageryKeys));
      continue;
    }
    if (k == "path") path = &node;
    readKey(r, k, node, prefix + k, directory, source);
  }
  if (path == nullptr) r.fail(t.source(), prefix + "path", "missing (required)");
  // Opened once the extent is known (it replaces the file's georeferencing).
  if (path != nullptr && r.errorCount() == before) {
    if (Result<ImageryLayer> layer = openImageryLayer(source, 6371000.0); !layer)
      r.fail(path->source(), prefix + "path", fmt::format("'{}' {}", source.path, layer.error().message));
  }
  imagery.push_back(std::move(source));
}

}  // namespace

void readImagery(PlanetTomlReader& r, const toml::node& node, const std::string& planetDirectory,
                 std::vector<ImagerySource>& imagery) {
  const toml::array* list = r.arrayOfTables(node, "imagery");
  if (list == nullptr) return;
  if (list->size() > std::size_t(kMaxImagerySources)) {
    r.fail((*list)[std::size_t(kMaxImagerySources)].source(), "imagery",
           fmt::format("at most {} imagery rasters", kMaxImagerySources));
  }
  for (std::size_t i = 0; i < list->size(); ++i) readOne(r, *(*list)[i].as_table(), i, planetDirectory, imagery);
}

std::string formatImageryToml(const std::vector<ImagerySource>& imagery) {
  std::string out;
  auto line = std::back_inserter(out);
  for (const ImagerySource& img : imagery) {
    fmt::format_to(line, "\n[[imagery]]\npath = {}\npriority = {}\nopacity = {}\n", tomlQuoted(img.path), img.priority,
                   img.opacity);
    if (const auto& e = img.extent)
      fmt::format_to(line, "extent = [{}, {}, {}, {}]\n", e->lon_min_deg, e->lat_min_deg, e->lon_max_deg,
                     e->lat_max_deg);
    if (img.blend_m >= 0.0) fmt::format_to(line, "blend_m = {}\n", img.blend_m);
  }
  return out;
}

}  // namespace globe
