#include "planet/surface/land_cover_toml.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace globe {
namespace {

// One entry per [climate] key: its name is the Climate member's.
struct ClimateKey {
  std::string_view name;
  double Climate::*member;
};
constexpr ClimateKey kClimateKeys[] = {
    {"equator_temperature_c", &Climate::equator_temperature_c},
    {"pole_temperature_c", &Climate::pole_temperature_c},
    {"lapse_rate_c_per_km", &Climate::lapse_rate_c_per_km},
    {"temperature_noise_c", &Climate::temperature_noise_c},
    {"moisture_base", &Climate::moisture_base},
    {"moisture_noise", &Climate::moisture_noise},
    {"inland_drying_m", &Climate::inland_drying_m},
    {"noise_wavelength_m", &Climate::noise_wavelength_m},
    {"temperature_blend_c", &Climate::temperature_blend_c},
    {"moisture_blend", &Climate::moisture_blend},
    {"elevation_blend_m", &Climate::elevation_blend_m},
    {"slope_blend_deg", &Climate::slope_blend_deg},
};

constexpr auto kClimateKeyNames = [] {
  std::array<std::string_view, std::size(kClimateKeys)> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = kClimateKeys[i].name;
  return names;
}();

// What reading one [[land_cover]] table has seen.
struct ClassRead {
  LandCoverClass cls;
  std::string directory;  // the planet file's folder
  bool have_name = false;
  bool have_colour = false;
};

// [min, max] of numbers; an open end may be written -inf / inf (stored as -+kUnboundedRange, which
// is what the writer writes). Ranges and order are checked by appendLandCoverErrors.
void readRange(PlanetTomlReader& r, const toml::node& node, const std::string& field, double& min, double& max) {
  r.remember(field, node.source());
  const toml::array* a = node.as_array();
  if (a == nullptr || a->size() != 2) {
    r.fail(node.source(), field,
           a == nullptr ? fmt::format("expected an array [min, max], got {}", tomlTypeName(node.type()))
                        : fmt::format("expected 2 values [min, max], got {}", a->size()));
    return;
  }
  std::array<double, 2> v{};
  const std::size_t before = r.errorCount();
  for (std::size_t i = 0; i < 2; ++i) {
    const toml::node& end = (*a)[i];
    if (const auto* f = end.as_floating_point(); f != nullptr && std::isinf(f->get())) {
      v[i] = std::copysign(kUnboundedRange, f->get());
    } else if (auto x = r.number(end, field)) {
      v[i] = *x;
    }
  }
  r.remember(field, node.source());  // number() moved it to the component
  if (r.errorCount() != before) return;
  min = v[0];
  max = v[1];
}

bool hasPngSignature(const std::string& path) {
  constexpr char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
  std::ifstream in(path, std::ios::binary);
  char head[8] = {};
  return in.read(head, sizeof head) && std::equal(std::begin(head), std::end(head), std::begin(kSignature));
}

void readTexture(PlanetTomlReader& r, const toml::node& node, const std::string& field, ClassRead& read) {
  auto path = r.path(node, field, read.directory, " (leave the key out for the procedural detail)");
  if (!path) return;
  read.cls.texture = *path;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(read.cls.texture, ec)) {
    r.fail(node.source(), field, fmt::format("no such file '{}'", read.cls.texture));
  } else if (!hasPngSignature(read.cls.texture)) {
    r.fail(node.source(), field, fmt::format("'{}' is not a PNG file", read.cls.texture));
  }
}

using ClassKeyReader = void (*)(PlanetTomlReader& r, const toml::node& node, const std::string& field, ClassRead& read);

// One entry per key a [[land_cover]] table may hold; a key not here is unknown.
struct ClassKey {
  std::string_view name;
  ClassKeyReader read;
};
constexpr ClassKey kClassKeys[] = {
    {"name",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, ClassRead& read) {
       read.have_name = true;
       if (auto v = r.string(node, field)) read.cls.name = *v;
     }},
    {"colour",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, ClassRead& read) {
       read.have_colour = true;
       if (auto v = r.colour(node, field)) read.cls.colour = *v;
     }},
    {"temperature_c",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, ClassRead& read) {
       readRange(r, node, field, read.cls.temperature_min_c, read.cls.temperature_max_c);
     }},
    {"moisture", [](PlanetTomlReader& r, const toml::node& node, const std::string& field,
                    ClassRead& read) { readRange(r, node, field, read.cls.moisture_min, read.cls.moisture_max); }},
    {"elevation_m",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, ClassRead& read) {
       readRange(r, node, field, read.cls.elevation_min_m, read.cls.elevation_max_m);
     }},
    {"slope_deg", [](PlanetTomlReader& r, const toml::node& node, const std::string& field,
                     ClassRead& read) { readRange(r, node, field, read.cls.slope_min_deg, read.cls.slope_max_deg); }},
    {"detail_contrast",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, ClassRead& read) {
       if (auto v = r.number(node, field)) read.cls.detail_contrast = *v;
     }},
    {"texture", readTexture},
};

constexpr auto kClassKeyNames = [] {
  std::array<std::string_view, std::size(kClassKeys)> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = kClassKeys[i].name;
  return names;
}();

void readClass(PlanetTomlReader& r, const toml::table& t, std::size_t index, const std::string& directory,
               std::vector<LandCoverClass>& classes) {
  ClassRead read;
  read.directory = directory;
  const std::string prefix = fmt::format("land_cover[{}].", index);
  r.remember(prefix + "name", t.source());
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    const std::string field = prefix + k;
    const auto* entry =
        std::find_if(std::begin(kClassKeys), std::end(kClassKeys), [&](const ClassKey& e) { return e.name == k; });
    if (entry == std::end(kClassKeys)) {
      r.fail(key.source(), field, unknownKeyMessage(k, kClassKeyNames));
      continue;
    }
    entry->read(r, node, field, read);
  }
  if (!read.have_name) r.fail(t.source(), prefix + "name", "missing (required)");
  if (!read.have_colour) r.fail(t.source(), prefix + "colour", "missing (required)");
  // Kept even when broken, so the later classes' problems are found too.
  classes.push_back(std::move(read.cls));
}

// "[lo, hi]" with the writer's numbers (an open end is +-1e30, which reads back to the same).
std::string range(double lo, double hi) { return fmt::format("[{}, {}]", lo, hi); }

}  // namespace

void readClimate(PlanetTomlReader& r, const toml::node& node, Climate& climate) {
  const toml::table* t = r.table(node, "climate", "[climate]");
  if (t == nullptr) return;
  for (auto&& [key, value] : *t) {
    const std::string k(key.str());
    const std::string field = "climate." + k;
    const auto* entry = std::find_if(std::begin(kClimateKeys), std::end(kClimateKeys),
                                     [&](const ClimateKey& e) { return e.name == k; });
    if (entry == std::end(kClimateKeys)) {
      r.fail(key.source(), field, unknownKeyMessage(k, kClimateKeyNames));
    } else if (auto v = r.number(value, field)) {
      climate.*(entry->member) = *v;
    }
  }
}

void readLandCoverClasses(PlanetTomlReader& r, const toml::node& node, const std::string& planetDirectory,
                          std::vector<LandCoverClass>& classes) {
  const toml::array* list = r.arrayOfTables(node, "land_cover");
  if (list == nullptr) return;
  const auto most = static_cast<std::size_t>(kMaxLandCoverClasses);
  if (list->size() > most) {
    r.fail((*list)[most].source(), "land_cover", fmt::format("at most {} classes", kMaxLandCoverClasses));
  }
  for (std::size_t i = 0; i < list->size(); ++i) readClass(r, *(*list)[i].as_table(), i, planetDirectory, classes);
}

void checkLandCoverTables(PlanetTomlReader& r, const toml::table& root) {
  const toml::node* climate = root.get("climate");
  if (climate != nullptr && !root.contains("land_cover")) {
    r.fail(climate->source(), "climate", "[climate] needs at least one [[land_cover]] class");
  }
}

std::string formatLandCoverToml(const LandCover& cover) {
  if (!cover.enabled()) return {};
  std::string out = "\n[climate]\n";
  auto line = std::back_inserter(out);
  for (const ClimateKey& k : kClimateKeys) fmt::format_to(line, "{} = {}\n", k.name, cover.climate.*(k.member));
  const LandCoverClass unbounded;
  for (const LandCoverClass& c : cover.classes) {
    fmt::format_to(line, "\n[[land_cover]]\nname = {}\ncolour = [{}, {}, {}]\n", tomlQuoted(c.name), c.colour.x,
                   c.colour.y, c.colour.z);
    const std::pair<double, double> defaults[] = {{unbounded.temperature_min_c, unbounded.temperature_max_c},
                                                  {unbounded.moisture_min, unbounded.moisture_max},
                                                  {unbounded.elevation_min_m, unbounded.elevation_max_m},
                                                  {unbounded.slope_min_deg, unbounded.slope_max_deg}};
    const std::pair<double, double> ranges[] = {{c.temperature_min_c, c.temperature_max_c},
                                                {c.moisture_min, c.moisture_max},
                                                {c.elevation_min_m, c.elevation_max_m},
                                                {c.slope_min_deg, c.slope_max_deg}};
    const char* const names[] = {"temperature_c", "moisture", "elevation_m", "slope_deg"};
    for (std::size_t i = 0; i < std::size(names); ++i) {
      if (ranges[i] != defaults[i])
        fmt::format_to(line, "{} = {}\n", names[i], range(ranges[i].first, ranges[i].second));
    }
    fmt::format_to(line, "detail_contrast = {}\n", c.detail_contrast);
    if (!c.texture.empty()) fmt::format_to(line, "texture = {}\n", tomlQuoted(c.texture));
  }
  return out;
}

}  // namespace globe
