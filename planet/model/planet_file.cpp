#include "planet/model/planet_file.h"
#include "planet/core/input_file.h"

#include "planet/atmosphere/atmosphere_toml.h"
#include "planet/core/planet_toml_reader.h"
#include "planet/sources/imagery_toml.h"
#include "planet/sources/source_toml.h"
#include "planet/surface/land_cover_toml.h"
#include "planet/vectors/vector_toml.h"

#include <fmt/format.h>
#include <toml++/toml.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace globe {
namespace {

constexpr std::string_view kTopKeys[] = {"name",
                                         "radius_m",
                                         "shape",
                                         "seed",
                                         "sea_level_m",
                                         "surface_gravity_m_s2",
                                         "default_quality",
                                         "layers",
                                         "colour_ramp",
                                         "rock",
                                         "snow",
                                         "water",
                                         "sources",
                                         "imagery",
                                         "vectors",
                                         "atmosphere",
                                         "climate",
                                         "land_cover"};
constexpr std::string_view kShapeKeys[] = {"equatorial_radius_m", "flattening"};
constexpr std::string_view kStopKeys[] = {"elevation_m", "colour"};
constexpr std::string_view kRockKeys[] = {"slope_deg", "blend_deg", "colour"};
constexpr std::string_view kSnowKeys[] = {"elevation_m", "blend_m", "max_slope_deg", "colour"};
constexpr std::string_view kWaterKeys[] = {"shallow_colour", "deep_colour", "depth_scale_m"};

// What reading one [[layers]] table has seen: the layer and the nodes the cross-key checks need.
struct LayerRead {
  ElevationLayer layer;
  std::string prefix;  // "layers[i]."
  bool have_octaves = false;
  bool have_amplitude = false;
  const toml::node* wavelength = nullptr;
  const toml::node* frequency = nullptr;
  std::string modulator;
  const toml::node* modulator_node = nullptr;
  const toml::node* low = nullptr;
  const toml::node* high = nullptr;
  const toml::node* floor = nullptr;
};

using LayerKeyReader = void (*)(PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read);

void readLayerKind(PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
  auto v = r.string(node, field);
  if (!v) return;
  for (LayerKind kind : {LayerKind::kFbm, LayerKind::kRidged, LayerKind::kBillow, LayerKind::kCraters}) {
    if (*v == layerKindName(kind)) {
      read.layer.kind = kind;
      return;
    }
  }
  r.fail(node.source(), field, fmt::format("unknown kind '{}' (fbm, ridged, billow, craters)", *v));
}

void readLayerOctaves(PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
  read.have_octaves = true;
  auto v = r.integer(node, field);
  if (!v) return;
  if (*v < 1 || *v > kMaxOctavesPerLayer) {
    r.fail(node.source(), field, fmt::format("must be in [1, {}]", kMaxOctavesPerLayer));
  } else {
    read.layer.octaves = static_cast<int>(*v);
  }
}

void readLayerFrequency(PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
  read.frequency = &node;
  auto v = r.number(node, field);
  if (!v) return;
  if (!(*v > 0.0)) {
    r.fail(node.source(), field, "must be > 0");
  } else {
    read.layer.wavelength_m = 1.0 / *v;
    r.rememberAs(read.prefix + "wavelength_m", field, node.source(), /*inverse=*/true);
  }
}

// One entry per key a [[layers]] table may hold; a key not here is unknown.
struct LayerKey {
  std::string_view name;
  LayerKeyReader read;
};
constexpr LayerKey kLayerKeyReaders[] = {
    {"name",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
       if (auto v = r.string(node, field)) read.layer.name = *v;
     }},
    {"kind", readLayerKind},
    {"octaves", readLayerOctaves},
    {"wavelength_m",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
       read.wavelength = &node;
       if (auto v = r.number(node, field)) read.layer.wavelength_m = *v;
     }},
    {"frequency_per_m", readLayerFrequency},
    {"lacunarity",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
       if (auto v = r.number(node, field)) read.layer.lacunarity = *v;
     }},
    {"gain",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
       if (auto v = r.number(node, field)) read.layer.gain = *v;
     }},
    {"amplitude_m",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
       read.have_amplitude = true;
       if (auto v = r.number(node, field)) read.layer.amplitude_m = *v;
     }},
    {"offset_m",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
       if (auto v = r.number(node, field)) read.layer.offset_m = *v;
     }},
    {"modulated_by",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
       read.modulator_node = &node;
       if (auto v = r.string(node, field)) read.modulator = *v;
     }},
    {"modulation_low_m",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
       read.low = &node;
       if (auto v = r.number(node, field)) read.layer.modulation_low_m = *v;
     }},
    {"modulation_high_m",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
       read.high = &node;
       if (auto v = r.number(node, field)) read.layer.modulation_high_m = *v;
     }},
    {"modulation_floor",
     [](PlanetTomlReader& r, const toml::node& node, const std::string& field, LayerRead& read) {
       read.floor = &node;
       if (auto v = r.number(node, field)) read.layer.modulation_floor = *v;
     }},
};

// The key names, in table order, for unknown-key suggestions.
constexpr auto kLayerKeys = [] {
  std::array<std::string_view, std::size(kLayerKeyReaders)> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = kLayerKeyReaders[i].name;
  return names;
}();

// The rules between keys: required ones, exclusive ones, and the modulator's.
void checkLayerKeys(PlanetTomlReader& r, const toml::table& t, const PlanetDescription& planet, LayerRead& read) {
  const std::string& p = read.prefix;
  if (!read.have_octaves) r.fail(t.source(), p + "octaves", "missing (required)");
  if (!read.have_amplitude) r.fail(t.source(), p + "amplitude_m", "missing (required)");
  if (read.wavelength != nullptr && read.frequency != nullptr) {
    r.fail(read.frequency->source(), p + "frequency_per_m", "give wavelength_m or frequency_per_m, not both");
  }
  if (read.wavelength == nullptr && read.frequency == nullptr) {
    r.fail(t.source(), p + "wavelength_m", "missing (required, or frequency_per_m)");
  }
  if (read.modulator_node == nullptr) {
    // Without a modulator these keys would be silently ignored: almost always a forgotten line.
    for (const auto& [node, name] : {std::pair{read.low, "modulation_low_m"}, std::pair{read.high, "modulation_high_m"},
                                     std::pair{read.floor, "modulation_floor"}}) {
      if (node != nullptr) r.fail(node->source(), p + name, "has no effect without modulated_by");
    }
    return;
  }
  if (read.modulator_node->is_string()) {
    for (std::size_t j = 0; j < planet.layers.size(); ++j) {
      if (planet.layers[j].name == read.modulator) read.layer.modulated_by = static_cast<int>(j);
    }
    if (read.layer.modulated_by < 0) {
      r.fail(read.modulator_node->source(), p + "modulated_by",
             fmt::format("no earlier layer named '{}'", read.modulator));
    }
  }
  if (read.low == nullptr) r.fail(t.source(), p + "modulation_low_m", "missing (required with modulated_by)");
  if (read.high == nullptr) r.fail(t.source(), p + "modulation_high_m", "missing (required with modulated_by)");
}

void readLayer(PlanetTomlReader& r, const toml::table& t, std::size_t index, PlanetDescription& planet) {
  LayerRead read;
  read.prefix = fmt::format("layers[{}].", index);
  read.layer.name = fmt::format("layer{}", index);
  r.remember(read.prefix + "name", t.source());
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    const std::string field = read.prefix + k;
    const auto* entry = std::find_if(std::begin(kLayerKeyReaders), std::end(kLayerKeyReaders),
                                     [&](const LayerKey& e) { return e.name == k; });
    if (entry == std::end(kLayerKeyReaders)) {
      r.fail(key.source(), field, unknownKeyMessage(k, kLayerKeys));
      continue;
    }
    entry->read(r, node, field, read);
  }
  checkLayerKeys(r, t, planet, read);
  // Kept even when broken, so later layers can name it and their own problems are found too.
  planet.layers.push_back(std::move(read.layer));
}

void readStop(PlanetTomlReader& r, const toml::table& t, std::size_t index, ColourRamp& ramp) {
  const std::string p = fmt::format("colour_ramp[{}].", index);
  ColourRampStop stop;
  bool have_elevation = false;
  bool have_colour = false;
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    if (!isKnownKey(k, kStopKeys)) {
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

void readRock(PlanetTomlReader& r, const toml::table& t, ColourRamp& ramp) {
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    const std::string field = "rock." + k;
    if (!isKnownKey(k, kRockKeys)) {
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

void readSnow(PlanetTomlReader& r, const toml::table& t, ColourRamp& ramp) {
  ramp.snow = true;
  bool have_elevation = false;
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    const std::string field = "snow." + k;
    if (!isKnownKey(k, kSnowKeys)) {
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

void readWater(PlanetTomlReader& r, const toml::table& t, Water& water) {
  water.enabled = true;
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    const std::string field = "water." + k;
    if (!isKnownKey(k, kWaterKeys)) {
      r.fail(key.source(), field, unknownKeyMessage(k, kWaterKeys));
    } else if (k == "shallow_colour") {
      if (auto v = r.colour(node, field)) water.shallow_colour = *v;
    } else if (k == "deep_colour") {
      if (auto v = r.colour(node, field)) water.deep_colour = *v;
    } else if (k == "depth_scale_m") {
      if (auto v = r.number(node, field)) water.depth_scale_m = *v;
    }
  }
}

// shape = { equatorial_radius_m = a, flattening = f }: the reference ellipsoid instead of radius_m's
// sphere. Both keys are required; validation errors on radius_m / flattening name these keys.
void readShape(PlanetTomlReader& r, const toml::table& t, PlanetDescription& planet) {
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    if (!isKnownKey(k, kShapeKeys)) {
      r.fail(key.source(), "shape." + k, unknownKeyMessage(k, kShapeKeys));
      continue;
    }
    const bool radius = k == "equatorial_radius_m";
    if (auto v = r.number(node, "shape." + k)) (radius ? planet.radius_m : planet.flattening) = *v;
    r.rememberAs(radius ? "radius_m" : "flattening", "shape." + k, node.source());
  }
  for (std::string_view k : kShapeKeys)
    if (!t.contains(k)) r.fail(t.source(), "shape." + std::string(k), "missing (required in shape)");
}

void readTopLevel(PlanetTomlReader& r, const std::string& k, const toml::node& node, PlanetDescription& planet) {
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
  } else if (k == "surface_gravity_m_s2") {
    if (auto v = r.number(node, k)) planet.surface_gravity_m_s2 = *v;
  } else if (k == "default_quality") {
    if (auto v = r.string(node, k)) {
      if (auto preset = qualityPresetFromName(*v)) {
        planet.default_quality = *preset;
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
  } else if (k == "shape") {
    if (const toml::table* t = r.table(node, k, "shape = { ... }")) readShape(r, *t, planet);
  } else if (k == "rock") {
    if (const toml::table* t = r.table(node, k, "[rock]")) readRock(r, *t, planet.colour_ramp);
  } else if (k == "snow") {
    if (const toml::table* t = r.table(node, k, "[snow]")) readSnow(r, *t, planet.colour_ramp);
  } else if (k == "water") {
    if (const toml::table* t = r.table(node, k, "[water]")) readWater(r, *t, planet.water);
  }
}

PlanetFileCheck readPlanet(const toml::table& root, std::string_view source_name) {
  PlanetTomlReader r{std::string(source_name)};
  PlanetFileCheck check;
  PlanetDescription& planet = check.planet;
  planet.name = std::filesystem::path(source_name).stem().string();
  const std::string directory = std::filesystem::path(source_name).parent_path().string();
  const toml::node* radius = nullptr;
  const toml::node* shape = nullptr;
  bool have_layers = false;

  for (auto&& [key, node] : root) {
    const std::string k(key.str());
    if (!isKnownKey(k, kTopKeys)) {
      r.fail(key.source(), k, unknownKeyMessage(k, kTopKeys));
      continue;
    }
    if (k == "radius_m") radius = &node;
    if (k == "shape") shape = &node;
    have_layers = have_layers || k == "layers";
    if (k == "atmosphere") {
      readAtmosphere(r, node, planet.atmosphere.emplace());
    } else if (k == "sources") {
      readSources(r, node, directory, planet.sources);
    } else if (k == "imagery") {
      readImagery(r, node, directory, planet.imagery);
    } else if (k == "vectors") {
      readVectors(r, node, directory, planet.vectors);
    } else if (k == "climate") {
      readClimate(r, node, planet.land_cover.climate);
    } else if (k == "land_cover") {
      readLandCoverClasses(r, node, directory, planet.land_cover.classes);
    } else {
      readTopLevel(r, k, node, planet);
    }
  }
  if (radius == nullptr && shape == nullptr) r.fail(root.source(), "radius_m", "missing (required, or shape)");
  if (radius != nullptr && shape != nullptr) {
    r.fail(shape->source(), "shape", "give radius_m (a sphere) or shape (an ellipsoid), not both");
  }
  if (!have_layers) r.fail(root.source(), "layers", "missing (required, at least one [[layers]])");
  checkLandCoverTables(r, root);

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
    check.errors.push_back(Error::at(std::string(source_name), static_cast<int>(e.source().begin.line),
                                     static_cast<int>(e.source().begin.column), "", std::string(e.description())));
    return check;
  }
  return readPlanet(root, source_name);
}

PlanetFileCheck checkPlanetFile(const std::string& path) {
  Result<std::string> text = readInputFile(path, "planet file");
  if (!text) {
    PlanetFileCheck check;
    check.errors.push_back(text.error());
    return check;
  }
  return checkPlanetToml(*text, path);
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
