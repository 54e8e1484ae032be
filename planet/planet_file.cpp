#include "planet/planet_file.h"

#include <fmt/format.h>
#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

namespace globe {
namespace {

constexpr std::string_view kTopKeys[] = {"name", "radius_m", "seed", "sea_level_m", "layers"};
constexpr std::string_view kLayerKeys[] = {
    "name",        "kind",     "octaves",      "wavelength_m",     "frequency_per_m",   "lacunarity",      "gain",
    "amplitude_m", "offset_m", "modulated_by", "modulation_low_m", "modulation_high_m", "modulation_floor"};

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

// Reads values with their positions; the first error wins. Positions of every value read are kept
// so that errors found later by validatePlanet (by field path) point at the right line.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  bool failed() const { return error_.has_value(); }
  Error takeError() { return std::move(*error_); }

  void fail(const toml::source_region& where, std::string field, std::string message) {
    if (error_) return;
    error_ = Error{file_, static_cast<int>(where.begin.line), static_cast<int>(where.begin.column), std::move(field),
                   std::move(message)};
  }

  void remember(const std::string& field, const toml::source_region& where) { where_[field] = where; }

  Error locate(Error e) const {
    e.file = file_;
    auto it = where_.find(e.field);
    if (it != where_.end()) {
      e.line = static_cast<int>(it->second.begin.line);
      e.column = static_cast<int>(it->second.begin.column);
    }
    return e;
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

 private:
  std::string file_;
  std::optional<Error> error_;
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
  bool have_low = false;
  bool have_high = false;

  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    const std::string field = p + k;
    if (!isKnown(k, kLayerKeys)) {
      r.fail(key.source(), field, unknownKeyMessage(k, kLayerKeys));
      return;
    }
    if (k == "name") {
      if (auto v = r.string(node, field)) layer.name = *v;
    } else if (k == "kind") {
      if (auto v = r.string(node, field)) {
        if (*v == "fbm") {
          layer.kind = LayerKind::Fbm;
        } else if (*v == "ridged") {
          layer.kind = LayerKind::Ridged;
        } else if (*v == "billow") {
          layer.kind = LayerKind::Billow;
        } else {
          r.fail(node.source(), field, fmt::format("unknown kind '{}' (fbm, ridged, billow)", *v));
        }
      }
    } else if (k == "octaves") {
      if (auto v = r.integer(node, field)) {
        if (*v < 1 || *v > kMaxOctavesPerLayer) {
          r.fail(node.source(), field, fmt::format("must be in [1, {}]", kMaxOctavesPerLayer));
        } else {
          layer.octaves = static_cast<int>(*v);
          have_octaves = true;
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
      if (auto v = r.number(node, field)) layer.amplitude_m = *v;
      have_amplitude = true;
    } else if (k == "offset_m") {
      if (auto v = r.number(node, field)) layer.offset_m = *v;
    } else if (k == "modulated_by") {
      modulator_node = &node;
      if (auto v = r.string(node, field)) modulator = *v;
    } else if (k == "modulation_low_m") {
      if (auto v = r.number(node, field)) layer.modulation_low_m = *v;
      have_low = true;
    } else if (k == "modulation_high_m") {
      if (auto v = r.number(node, field)) layer.modulation_high_m = *v;
      have_high = true;
    } else if (k == "modulation_floor") {
      if (auto v = r.number(node, field)) layer.modulation_floor = *v;
    }
    if (r.failed()) return;
  }

  if (!have_octaves) return r.fail(t.source(), p + "octaves", "missing (required)");
  if (!have_amplitude) return r.fail(t.source(), p + "amplitude_m", "missing (required)");
  if (wavelength != nullptr && frequency != nullptr) {
    return r.fail(frequency->source(), p + "frequency_per_m", "give wavelength_m or frequency_per_m, not both");
  }
  if (wavelength == nullptr && frequency == nullptr) {
    return r.fail(t.source(), p + "wavelength_m", "missing (required, or frequency_per_m)");
  }
  if (modulator_node != nullptr) {
    for (std::size_t j = 0; j < planet.layers.size(); ++j) {
      if (planet.layers[j].name == modulator) layer.modulated_by = static_cast<int>(j);
    }
    if (layer.modulated_by < 0) {
      return r.fail(modulator_node->source(), p + "modulated_by",
                    fmt::format("no earlier layer named '{}'", modulator));
    }
    if (!have_low) return r.fail(t.source(), p + "modulation_low_m", "missing (required with modulated_by)");
    if (!have_high) return r.fail(t.source(), p + "modulation_high_m", "missing (required with modulated_by)");
  }
  planet.layers.push_back(std::move(layer));
}

Result<PlanetDescription> readPlanet(const toml::table& root, std::string_view source_name) {
  Reader r{std::string(source_name)};
  PlanetDescription planet;
  planet.name = std::filesystem::path(source_name).stem().string();
  bool have_radius = false;
  bool have_layers = false;

  for (auto&& [key, node] : root) {
    const std::string k(key.str());
    if (!isKnown(k, kTopKeys)) {
      r.fail(key.source(), k, unknownKeyMessage(k, kTopKeys));
      break;
    }
    if (k == "name") {
      if (auto v = r.string(node, k)) planet.name = *v;
    } else if (k == "radius_m") {
      if (auto v = r.number(node, k)) planet.radius_m = *v;
      have_radius = true;
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
    } else if (k == "layers") {
      have_layers = true;
      r.remember("layers", node.source());
      const toml::array* layers = node.as_array();
      if (layers == nullptr || !layers->is_array_of_tables()) {
        r.fail(node.source(), k, "expected an array of tables ([[layers]])");
        break;
      }
      if (layers->size() > static_cast<std::size_t>(kMaxElevationLayers)) {
        r.fail((*layers)[kMaxElevationLayers].source(), k, fmt::format("at most {} layers", kMaxElevationLayers));
        break;
      }
      for (std::size_t i = 0; i < layers->size() && !r.failed(); ++i) {
        readLayer(r, *(*layers)[i].as_table(), i, planet);
      }
    }
    if (r.failed()) break;
  }
  if (!r.failed() && !have_radius) r.fail(root.source(), "radius_m", "missing (required)");
  if (!r.failed() && !have_layers) r.fail(root.source(), "layers", "missing (required, at least one [[layers]])");
  if (r.failed()) return r.takeError();

  // Ranges and cross-field rules live in one place; point the error at the value that was read.
  if (Status s = validatePlanet(planet); !s.ok()) return r.locate(s.error());
  return planet;
}

}  // namespace

Result<PlanetDescription> parsePlanetToml(std::string_view text, std::string_view source_name) {
  toml::table root;
  try {
    root = toml::parse(text, source_name);
  } catch (const toml::parse_error& e) {
    return Error{std::string(source_name), static_cast<int>(e.source().begin.line),
                 static_cast<int>(e.source().begin.column), "", std::string(e.description())};
  }
  return readPlanet(root, source_name);
}

Result<PlanetDescription> loadPlanetFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path, 0, 0, "", "cannot open planet file"};
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return Error{path, 0, 0, "", "cannot read planet file"};
  return parsePlanetToml(text.str(), path);
}

}  // namespace globe
