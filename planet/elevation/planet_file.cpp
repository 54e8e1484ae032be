#include "planet/elevation/planet_file.h"

#include <fmt/format.h>
#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

namespace globe {
namespace {

constexpr std::string_view kTopKeys[] = {"name",   "radius_m",    "seed", "sea_level_m", "default_quality",
                                         "layers", "colour_ramp", "rock", "snow"};
constexpr std::string_view kLayerKeys[] = {
    "name",        "kind",     "octaves",      "wavelength_m",     "frequency_per_m",   "lacunarity",      "gain",
    "amplitude_m", "offset_m", "modulated_by", "modulation_low_m", "modulation_high_m", "modulation_floor"};

constexpr std::string_view kStopKeys[] = {"elevation_m", "colour"};
constexpr std::string_view kRockKeys[] = {"slope_deg", "blend_deg", "colour"};
constexpr std::string_view kSnowKeys[] = {"elevation_m", "blend_m", "max_slope_deg", "colour"};

std::string_view typeName(toml::node_type t) {
  switch (t) {
    case toml::node_type::none:
      return "nothing";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
  }
  return "a value";
}

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0U : 1U)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

template <std::size_t N>
bool isKnown(std::string_view key, const std::string_view (&known)[N]) {
  return std::find(std::begin(known), std::end(known), key) != std::end(known);
}

template <std::size_t N>
std::string unknownKeyMessage(std::string_view key, const std::string_view (&known)[N]) {
  std::string_view best;
  std::size_t best_distance = 4;  // suggest only close matches
  for (std::string_view k : known) {
    const std::size_t d = editDistance(key, k);
    // A key that is a prefix of a known one ("radius" -> "radius_m") is close too.
    const std::size_t score = k.starts_with(key) ? std::min<std::size_t>(d, 1) : d;
    if (score < best_distance) {
      best_distance = score;
      best = k;
    }
  }
  if (best.empty()) return "unknown key";
  return fmt::format("unknown key (did you mean '{}'?)", best);
}

// Reads values with their positions and collects every problem instead of stopping at the first:
// a value that fails to read keeps its default, so reading (and then validating) goes on. The
// positions of every value read are kept so that errors found later by validatePlanetAll (by field
// path) point at the right line; a field that already failed to read is not reported twice.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  std::size_t errorCount() const { return errors_.size(); }

  void fail(const toml::source_region& where, std::string field, std::string message) {
    failed_fields_.insert(field);
    errors_.push_back(Error{file_, static_cast<int>(where.begin.line), static_cast<int>(where.begin.column),
                            std::move(field), std::move(message)});
  }

  void remember(const std::string& field, const toml::source_region& where) { where_[field] = where; }

  // Adds validatePlanetAll's findings at the positions of the values they name.
  void addValidationErrors(std::vector<Error> found) {
    for (Error& e : found) {
      if (failed_fields_.count(e.field) != 0) continue;
      e.file = file_;
      auto it = where_.find(e.field);
      if (it != where_.end()) {
        e.line = static_cast<int>(it->second.begin.line);
        e.column = static_cast<int>(it->second.begin.column);
      }
      errors_.push_back(std::move(e));
    }
  }

  // Every error, in file order (then in the order found, for errors at one position).
  std::vector<Error> takeErrors() {
    std::stable_sort(errors_.begin(), errors_.end(), [](const Error& a, const Error& b) {
      return a.line != b.line ? a.line < b.line : a.column < b.column;
    });
    return std::move(errors_);
  }

  std::optional<double> number(const toml::node& node, const std::string& field) {
    remember(field, node.source());
    double v = 0.0;
    if (const auto* f = node.as_floating_point()) {
      v = f->get();
    } else if (const auto* i = node.as_integer()) {
      v = static_cast<double>(i->get());
    } else {
      fail(node.source(), field, fmt::format("expected a number, got {}", typeName(node.type())));
      return std::nullopt;
    }
    if (!std::isfinite(v)) {
      fail(node.source(), field, "must be finite (not nan or inf)");
      return std::nullopt;
    }
    return v;
  }

  std::optional<std::int64_t> integer(const toml::node& node, const std::string& field) {
    remember(field, node.source());
    if (const auto* i = node.as_integer()) return i->get();
    fail(node.source(), field, fmt::format("expected an integer, got {}", typeName(node.type())));
    return std::nullopt;
  }

  std::optional<std::string> string(const toml::node& node, const std::string& field) {
    remember(field, node.source());
    if (const auto* s = node.as_string()) return s->get();
    fail(node.source(), field, fmt::format("expected a string, got {}", typeName(node.type())));
    return std::nullopt;
  }

  // [r, g, b], linear; the range [0, 1] is checked by validation.
  std::optional<glm::vec3> colour(const toml::node& node, const std::string& field) {
    remember(field, node.source());
    const toml::array* a = node.as_array();
    if (a == nullptr || a->size() != 3) {
      fail(node.source(), field,
           a == nullptr ? fmt::format("expected an array [r, g, b], got {}", typeName(node.type()))
                        : fmt::format("expected 3 components [r, g, b], got {}", a->size()));
      return std::nullopt;
    }
    glm::vec3 c(0.0f);
    const std::size_t before = errorCount();
    for (std::size_t i = 0; i < 3; ++i) {
      if (auto v = number((*a)[i], field)) c[static_cast<glm::length_t>(i)] = static_cast<float>(*v);
    }
    remember(field, node.source());  // number() moved it to the component
    if (errorCount() != before) return std::nullopt;
    return c;
  }

  const toml::table* table(const toml::node& node, const std::string& field, std::string_view how) {
    remember(field, node.source());
    if (const toml::table* t = node.as_table()) return t;
    fail(node.source(), field, fmt::format("expected a table ({}), got {}", how, typeName(node.type())));
    return nullptr;
  }

  // The elements of an array of tables ([[name]]); reports anything else.
  const toml::array* arrayOfTables(const toml::node& node, const std::string& field) {
    remember(field, node.source());
    const toml::array* a = node.as_array();
    if (a == nullptr || !a->is_array_of_tables()) {
      fail(node.source(), field, fmt::format("expected an array of tables ([[{}]])", field));
      return nullptr;
    }
    return a;
  }

 private:
  std::string file_;
  std::vector<Error> errors_;
  std::set<std::string> failed_fields_;
  std::map<std::string, toml::source_region> where_;
};

void readLayer(Reader& r, const toml::table& t, std::size_t index, PlanetDescription& planet) {
  const std::string p = fmt::format("layers[{}].", index);
  ElevationLayer layer;
  layer.name = fmt::format("layer{}", index);
  r.remember(p + "name", t.source());
  bool have_octaves = false;
  bool have_amplitude = false;
  const toml::node* wavelength = nullptr;
  const toml::node* frequency = nullptr;
  std::string modulator;
  const toml::node* modulator_node = nullptr;
  const toml::node* low = nullptr;
  const toml::node* high = nullptr;
  const toml::node* floor = nullptr;

  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    const std::string field = p + k;
    if (!isKnown(k, kLayerKeys)) {
      r.fail(key.source(), field, unknownKeyMessage(k, kLayerKeys));
      continue;
    }
    if (k == "name") {
      if (auto v = r.string(node, field)) layer.name = *v;
    } else if (k == "kind") {
      if (auto v = r.string(node, field)) {
        if (*v == "fbm") {
          layer.kind = LayerKind::kFbm;
        } else if (*v == "ridged") {
          layer.kind = LayerKind::kRidged;
        } else if (*v == "billow") {
          layer.kind = LayerKind::kBillow;
        } else {
          r.fail(node.source(), field, fmt::format("unknown kind '{}' (fbm, ridged, billow)", *v));
        }
      }
    } else if (k == "octaves") {
      have_octaves = true;
      if (auto v = r.integer(node, field)) {
        if (*v < 1 || *v > kMaxOctavesPerLayer) {
          r.fail(node.source(), field, fmt::format("must be in [1, {}]", kMaxOctavesPerLayer));
        } else {
          layer.octaves = static_cast<int>(*v);
        }
      }
    } else if (k == "wavelength_m") {
      wavelength = &node;
      if (auto v = r.number(node, field)) layer.wavelength_m = *v;
    } else if (k == "frequency_per_m") {
      frequency = &node;
      if (auto v = r.number(node, field)) {
        if (!(*v > 0.0)) {
          r.fail(node.source(), field, "must be > 0");
        } else {
          layer.wavelength_m = 1.0 / *v;
          r.remember(p + "wavelength_m", node.source());
        }
      }
    } else if (k == "lacunarity") {
      if (auto v = r.number(node, field)) layer.lacunarity = *v;
    } else if (k == "gain") {
      if (auto v = r.number(node, field)) layer.gain = *v;
    } else if (k == "amplitude_m") {
      have_amplitude = true;
      if (auto v = r.number(node, field)) layer.amplitude_m = *v;
    } else if (k == "offset_m") {
      if (auto v = r.number(node, field)) layer.offset_m = *v;
    } else if (k == "modulated_by") {
      modulator_node = &node;
      if (auto v = r.string(node, field)) modulator = *v;
    } else if (k == "modulation_low_m") {
      low = &node;
      if (auto v = r.number(node, field)) layer.modulation_low_m = *v;
    } else if (k == "modulation_high_m") {
      high = &node;
      if (auto v = r.number(node, field)) layer.modulation_high_m = *v;
    } else if (k == "modulation_floor") {
      floor = &node;
      if (auto v = r.number(node, field)) layer.modulation_floor = *v;
    }
  }

  if (!have_octaves) r.fail(t.source(), p + "octaves", "missing (required)");
  if (!have_amplitude) r.fail(t.source(), p + "amplitude_m", "missing (required)");
  if (wavelength != nullptr && frequency != nullptr) {
    r.fail(frequency->source(), p + "frequency_per_m", "give wavelength_m or frequency_per_m, not both");
  }
  if (wavelength == nullptr && frequency == nullptr) {
    r.fail(t.source(), p + "wavelength_m", "missing (required, or frequency_per_m)");
  }
  if (modulator_node != nullptr) {
    if (modulator_node->is_string()) {
      for (std::size_t j = 0; j < planet.layers.size(); ++j) {
        if (planet.layers[j].name == modulator) layer.modulated_by = static_cast<int>(j);
      }
      if (layer.modulated_by < 0) {
        r.fail(modulator_node->source(), p + "modulated_by", fmt::format("no earlier layer named '{}'", modulator));
      }
    }
    if (low == nullptr) r.fail(t.source(), p + "modulation_low_m", "missing (required with modulated_by)");
    if (high == nullptr) r.fail(t.source(), p + "modulation_high_m", "missing (required with modulated_by)");
  } else {
    // Without a modulator these keys would be silently ignored: almost always a forgotten line.
    for (const auto& [node, name] : {std::pair{low, "modulation_low_m"}, std::pair{high, "modulation_high_m"},
                                     std::pair{floor, "modulation_floor"}}) {
      if (node != nullptr) r.fail(node->source(), p + name, "has no effect without modulated_by");
    }
  }
  // Kept even when broken, so later layers can name it and their own problems are found too.
  planet.layers.push_back(std::move(layer));
}

void readStop(Reader& r, const toml::table& t, std::size_t index, ColourRamp& ramp) {
  const std::string p = fmt::format("colour_ramp[{}].", index);
  ColourRampStop stop;
  bool have_elevation = false;
  bool have_colour = false;
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    if (!isKnown(k, kStopKeys)) {
      r.fail(key.source(), p + k, unknownKeyMessage(k, kStopKeys));
    } else if (k == "elevation_m") {
      have_elevation = true;
      if (auto v = r.number(node, p + k)) stop.elevation_m = *v;
    } else if (k == "colour") {
      have_colour = true;
      if (auto v = r.colour(node, p + k)) stop.colour = *v;
    }
  }
  if (!have_elevation) r.fail(t.source(), p + "elevation_m", "missing (required)");
  if (!have_colour) r.fail(t.source(), p + "colour", "missing (required)");
  ramp.stops.push_back(stop);
}

void readRock(Reader& r, const toml::table& t, ColourRamp& ramp) {
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    const std::string field = "rock." + k;
    if (!isKnown(k, kRockKeys)) {
      r.fail(key.source(), field, unknownKeyMessage(k, kRockKeys));
    } else if (k == "slope_deg") {
      if (auto v = r.number(node, field)) ramp.rock_slope_deg = *v;
    } else if (k == "blend_deg") {
      if (auto v = r.number(node, field)) ramp.rock_blend_deg = *v;
    } else if (k == "colour") {
      if (auto v = r.colour(node, field)) ramp.rock_colour = *v;
    }
  }
}

void readSnow(Reader& r, const toml::table& t, ColourRamp& ramp) {
  ramp.snow = true;
  bool have_elevation = false;
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    const std::string field = "snow." + k;
    if (!isKnown(k, kSnowKeys)) {
      r.fail(key.source(), field, unknownKeyMessage(k, kSnowKeys));
    } else if (k == "elevation_m") {
      have_elevation = true;
      if (auto v = r.number(node, field)) ramp.snow_elevation_m = *v;
    } else if (k == "blend_m") {
      if (auto v = r.number(node, field)) ramp.snow_blend_m = *v;
    } else if (k == "max_slope_deg") {
      if (auto v = r.number(node, field)) ramp.snow_max_slope_deg = *v;
    } else if (k == "colour") {
      if (auto v = r.colour(node, field)) ramp.snow_colour = *v;
    }
  }
  if (!have_elevation) r.fail(t.source(), "snow.elevation_m", "missing (required in [snow])");
}

void readTopLevel(Reader& r, const std::string& k, const toml::node& node, PlanetDescription& planet) {
  if (k == "name") {
    if (auto v = r.string(node, k)) planet.name = *v;
  } else if (k == "radius_m") {
    if (auto v = r.number(node, k)) planet.radius_m = *v;
  } else if (k == "seed") {
    if (auto v = r.integer(node, k)) {
      if (*v < 0) {
        r.fail(node.source(), k, "must be >= 0");
      } else {
        planet.seed = static_cast<std::uint64_t>(*v);
      }
    }
  } else if (k == "sea_level_m") {
    if (auto v = r.number(node, k)) planet.sea_level_m = *v;
  } else if (k == "default_quality") {
    if (auto v = r.string(node, k)) {
      if (*v == "fast") {
        planet.default_quality = QualityPreset::kFast;
      } else if (*v == "balanced") {
        planet.default_quality = QualityPreset::kBalanced;
      } else if (*v == "exact") {
        planet.default_quality = QualityPreset::kExact;
      } else {
        r.fail(node.source(), k, fmt::format("unknown quality '{}' (fast, balanced, exact)", *v));
      }
    }
  } else if (k == "layers") {
    if (const toml::array* layers = r.arrayOfTables(node, k)) {
      if (layers->size() > static_cast<std::size_t>(kMaxElevationLayers)) {
        r.fail((*layers)[kMaxElevationLayers].source(), k, fmt::format("at most {} layers", kMaxElevationLayers));
      }
      for (std::size_t i = 0; i < layers->size(); ++i) readLayer(r, *(*layers)[i].as_table(), i, planet);
    }
  } else if (k == "colour_ramp") {
    if (const toml::array* stops = r.arrayOfTables(node, k)) {
      planet.colour_ramp.stops.clear();
      for (std::size_t i = 0; i < stops->size(); ++i) readStop(r, *(*stops)[i].as_table(), i, planet.colour_ramp);
    }
  } else if (k == "rock") {
    if (const toml::table* t = r.table(node, k, "[rock]")) readRock(r, *t, planet.colour_ramp);
  } else if (k == "snow") {
    if (const toml::table* t = r.table(node, k, "[snow]")) readSnow(r, *t, planet.colour_ramp);
  }
}

PlanetFileCheck readPlanet(const toml::table& root, std::string_view source_name) {
  Reader r{std::string(source_name)};
  PlanetFileCheck check;
  PlanetDescription& planet = check.planet;
  planet.name = std::filesystem::path(source_name).stem().string();
  bool have_radius = false;
  bool have_layers = false;

  for (auto&& [key, node] : root) {
    const std::string k(key.str());
    if (!isKnown(k, kTopKeys)) {
      r.fail(key.source(), k, unknownKeyMessage(k, kTopKeys));
      continue;
    }
    have_radius = have_radius || k == "radius_m";
    have_layers = have_layers || k == "layers";
    readTopLevel(r, k, node, planet);
  }
  if (!have_radius) r.fail(root.source(), "radius_m", "missing (required)");
  if (!have_layers) r.fail(root.source(), "layers", "missing (required, at least one [[layers]])");

  // Ranges and cross-field rules live in one place; each error points at the value that was read.
  std::vector<Error> invalid = validatePlanetAll(planet);
  if (invalid.empty() && r.errorCount() == 0) {
    if (auto e = terrainReachesCentre(planet)) invalid.push_back(std::move(*e));
  }
  r.addValidationErrors(std::move(invalid));
  check.errors = r.takeErrors();
  return check;
}

}  // namespace

PlanetFileCheck checkPlanetToml(std::string_view text, std::string_view source_name) {
  toml::table root;
  try {
    root = toml::parse(text, source_name);
  } catch (const toml::parse_error& e) {
    // toml++ does not recover from a syntax error, so it is the only problem reported.
    PlanetFileCheck check;
    check.errors.push_back(Error{std::string(source_name), static_cast<int>(e.source().begin.line),
                                 static_cast<int>(e.source().begin.column), "", std::string(e.description())});
    return check;
  }
  return readPlanet(root, source_name);
}

PlanetFileCheck checkPlanetFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  PlanetFileCheck check;
  if (!in) {
    check.errors.push_back(Error{path, 0, 0, "", "cannot open planet file"});
    return check;
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    check.errors.push_back(Error{path, 0, 0, "", "cannot read planet file"});
    return check;
  }
  return checkPlanetToml(text.str(), path);
}

Result<PlanetDescription> parsePlanetToml(std::string_view text, std::string_view source_name) {
  PlanetFileCheck check = checkPlanetToml(text, source_name);
  if (!check.ok()) return std::move(check.errors.front());
  return std::move(check.planet);
}

Result<PlanetDescription> loadPlanetFile(const std::string& path) {
  PlanetFileCheck check = checkPlanetFile(path);
  if (!check.ok()) return std::move(check.errors.front());
  return std::move(check.planet);
}

}  // namespace globe
