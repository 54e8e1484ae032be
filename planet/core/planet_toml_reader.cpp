#include "planet/core/planet_toml_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace globe {
namespace {

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

}  // namespace

std::string_view tomlTypeName(toml::node_type t) {
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

bool isKnownKey(std::string_view key, std::span<const std::string_view> known) {
  return std::find(known.begin(), known.end(), key) != known.end();
}

std::string tomlQuoted(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned>(static_cast<unsigned char>(c)));
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string unknownKeyMessage(std::string_view key, std::span<const std::string_view> known) {
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

void PlanetTomlReader::fail(const toml::source_region& where, std::string field, std::string message) {
  failed_fields_.insert(field);
  errors_.push_back(Error::at(file_, static_cast<int>(where.begin.line), static_cast<int>(where.begin.column),
                              std::move(field), std::move(message)));
}

void PlanetTomlReader::addValidationErrors(std::vector<Error> found) {
  for (Error& e : found) {
    if (failed_fields_.count(e.field) != 0) continue;
    e.file = file_;
    auto it = where_.find(e.field);
    if (it != where_.end()) {
      e.line = static_cast<int>(it->second.begin.line);
      e.column = static_cast<int>(it->second.begin.column);
    }
    if (auto spelled = spelledAs_.find(e.field); spelled != spelledAs_.end()) {
      const std::string& inFile = spelled->second.keyInFile;
      if (spelled->second.inverse) {
        const std::string shortName = e.field.substr(e.field.rfind('.') + 1);
        const std::string keyInFile = inFile.substr(inFile.rfind('.') + 1);
        e.message = fmt::format("gives {} = 1 / {}, which {}", shortName, keyInFile, e.message);
      }
      e.field = inFile;
    }
    errors_.push_back(std::move(e));
  }
}

std::vector<Error> PlanetTomlReader::takeErrors() {
  std::stable_sort(errors_.begin(), errors_.end(), [](const Error& a, const Error& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  return std::move(errors_);
}

std::optional<double> PlanetTomlReader::number(const toml::node& node, const std::string& field) {
  remember(field, node.source());
  double v = 0.0;
  if (const auto* f = node.as_floating_point()) {
    v = f->get();
  } else if (const auto* i = node.as_integer()) {
    v = static_cast<double>(i->get());
  } else {
    fail(node.source(), field, fmt::format("expected a number, got {}", tomlTypeName(node.type())));
    return std::nullopt;
  }
  if (!std::isfinite(v)) {
    fail(node.source(), field, "must be finite (not nan or inf)");
    return std::nullopt;
  }
  return v;
}

std::optional<std::int64_t> PlanetTomlReader::integer(const toml::node& node, const std::string& field) {
  remember(field, node.source());
  if (const auto* i = node.as_integer()) return i->get();
  fail(node.source(), field, fmt::format("expected an integer, got {}", tomlTypeName(node.type())));
  return std::nullopt;
}

std::optional<std::string> PlanetTomlReader::string(const toml::node& node, const std::string& field) {
  remember(field, node.source());
  if (const auto* s = node.as_string()) return s->get();
  fail(node.source(), field, fmt::format("expected a string, got {}", tomlTypeName(node.type())));
  return std::nullopt;
}

std::optional<std::string> PlanetTomlReader::path(const toml::node& node, const std::string& field,
                                                  const std::string& directory, std::string_view emptyHint) {
  auto v = string(node, field);
  if (!v) return std::nullopt;
  if (v->empty()) {
    fail(node.source(), field, fmt::format("must not be empty{}", emptyHint));
    return std::nullopt;
  }
  std::filesystem::path p(*v);
  if (p.is_relative() && !directory.empty()) p = std::filesystem::path(directory) / p;
  return p.lexically_normal().string();
}

std::optional<double> PlanetTomlReader::numberIn(const toml::node& node, const std::string& field, double low,
                                                 double high) {
  auto v = number(node, field);
  if (v && (*v < low || *v > high)) {
    fail(node.source(), field, fmt::format("must be in [{}, {}]", low, high));
    return std::nullopt;
  }
  return v;
}

std::optional<std::int64_t> PlanetTomlReader::integerIn(const toml::node& node, const std::string& field,
                                                        std::int64_t low, std::int64_t high) {
  auto v = integer(node, field);
  if (v && (*v < low || *v > high)) {
    fail(node.source(), field, fmt::format("must be in [{}, {}]", low, high));
    return std::nullopt;
  }
  return v;
}

std::optional<glm::vec3> PlanetTomlReader::colour(const toml::node& node, const std::string& field) {
  remember(field, node.source());
  const toml::array* a = node.as_array();
  if (a == nullptr || a->size() != 3) {
    fail(node.source(), field,
         a == nullptr ? fmt::format("expected an array [r, g, b], got {}", tomlTypeName(node.type()))
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

const toml::table* PlanetTomlReader::table(const toml::node& node, const std::string& field, std::string_view how) {
  remember(field, node.source());
  if (const toml::table* t = node.as_table()) return t;
  fail(node.source(), field, fmt::format("expected a table ({}), got {}", how, tomlTypeName(node.type())));
  return nullptr;
}

const toml::array* PlanetTomlReader::arrayOfTables(const toml::node& node, const std::string& field) {
  remember(field, node.source());
  const toml::array* a = node.as_array();
  if (a == nullptr || !a->is_array_of_tables()) {
    fail(node.source(), field, fmt::format("expected an array of tables ([[{}]])", field));
    return nullptr;
  }
  return a;
}

}  // namespace globe
