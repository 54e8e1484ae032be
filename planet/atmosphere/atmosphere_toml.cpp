#include "planet/atmosphere/atmosphere_toml.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <iterator>

namespace globe {
namespace {

// One entry per key: a number or a triple, and where it goes.
struct AtmosphereKey {
  std::string_view name;
  double AtmosphereParameters::*number = nullptr;
  glm::dvec3 AtmosphereParameters::*triple = nullptr;
};
constexpr AtmosphereKey kKeys[] = {
    {"thickness_m", &AtmosphereParameters::thickness_m},
    {"rayleigh_scattering_per_m", nullptr, &AtmosphereParameters::rayleigh_scattering_per_m},
    {"rayleigh_scale_height_m", &AtmosphereParameters::rayleigh_scale_height_m},
    {"mie_scattering_per_m", nullptr, &AtmosphereParameters::mie_scattering_per_m},
    {"mie_extinction_per_m", nullptr, &AtmosphereParameters::mie_extinction_per_m},
    {"mie_scale_height_m", &AtmosphereParameters::mie_scale_height_m},
    {"mie_g", &AtmosphereParameters::mie_g},
    {"ozone_absorption_per_m", nullptr, &AtmosphereParameters::ozone_absorption_per_m},
    {"ozone_centre_m", &AtmosphereParameters::ozone_centre_m},
    {"ozone_half_width_m", &AtmosphereParameters::ozone_half_width_m},
    {"sun_irradiance", nullptr, &AtmosphereParameters::sun_irradiance},
    {"sun_angular_radius_deg", &AtmosphereParameters::sun_angular_radius_deg},
    {"exposure", &AtmosphereParameters::exposure},
    {"ground_albedo", &AtmosphereParameters::ground_albedo},
};

constexpr auto kKeyNames = [] {
  std::array<std::string_view, std::size(kKeys)> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = kKeys[i].name;
  return names;
}();

// [a, b, c] of numbers (any range: validateAtmosphere checks it), read in double.
void readTriple(PlanetTomlReader& r, const toml::node& node, const std::string& field, glm::dvec3& out) {
  r.remember(field, node.source());
  const toml::array* a = node.as_array();
  if (a == nullptr || a->size() != 3) {
    r.fail(node.source(), field,
           a == nullptr ? fmt::format("expected an array [red, green, blue], got {}", tomlTypeName(node.type()))
                        : fmt::format("expected 3 components [red, green, blue], got {}", a->size()));
    return;
  }
  glm::dvec3 v(0.0);
  const std::size_t before = r.errorCount();
  for (std::size_t i = 0; i < 3; ++i) {
    if (auto x = r.number((*a)[i], field)) v[static_cast<glm::length_t>(i)] = *x;
  }
  r.remember(field, node.source());  // number() moved it to the component
  if (r.errorCount() == before) out = v;
}

}  // namespace

void readAtmosphere(PlanetTomlReader& r, const toml::node& node, AtmosphereParameters& atmosphere) {
  const toml::table* t = r.table(node, "atmosphere", "[atmosphere]");
  if (t == nullptr) return;
  for (auto&& [key, value] : *t) {
    const std::string k(key.str());
    const std::string field = "atmosphere." + k;
    const auto* entry =
        std::find_if(std::begin(kKeys), std::end(kKeys), [&](const AtmosphereKey& e) { return e.name == k; });
    if (entry == std::end(kKeys)) {
      r.fail(key.source(), field, unknownKeyMessage(k, kKeyNames));
    } else if (entry->number != nullptr) {
      if (auto v = r.number(value, field)) atmosphere.*(entry->number) = *v;
    } else {
      readTriple(r, value, field, atmosphere.*(entry->triple));
    }
  }
}

std::string formatAtmosphereToml(const AtmosphereParameters& atmosphere) {
  std::string out = "\n[atmosphere]\n";
  auto line = std::back_inserter(out);
  for (const AtmosphereKey& k : kKeys) {
    if (k.number != nullptr) {
      fmt::format_to(line, "{} = {}\n", k.name, atmosphere.*(k.number));
    } else {
      const glm::dvec3& v = atmosphere.*(k.triple);
      fmt::format_to(line, "{} = [{}, {}, {}]\n", k.name, v.x, v.y, v.z);
    }
  }
  return out;
}

}  // namespace globe
