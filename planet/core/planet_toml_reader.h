#pragma once
// Reading planet TOML values with their positions: the one reader planet_file.cpp and the sections'
// readers (atmosphere, sources, imagery, vectors, land cover) share. Every problem is collected
// instead of stopping at the first.
#include "planet/core/error.h"

#include <toml++/toml.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace globe {

// "a table", "an integer", ...: for "expected X, got Y" messages.
std::string_view tomlTypeName(toml::node_type t);

bool isKnownKey(std::string_view key, std::span<const std::string_view> known);

// A TOML basic string for `s`, quotes included, escaping what TOML requires (quote, backslash,
// control characters): what the planet file writer writes for names and paths.
std::string tomlQuoted(std::string_view s);

// "unknown key", with a suggestion when a known key is close ("did you mean 'radius_m'?").
std::string unknownKeyMessage(std::string_view key, std::span<const std::string_view> known);

// Reads values with their positions and collects every problem instead of stopping at the first:
// a value that fails to read keeps its default, so reading (and then validating) goes on. The
// positions of every value read are kept so that errors found later by validatePlanetAll (by field
// path) point at the right line; a field that already failed to read is not reported twice.
class PlanetTomlReader {
 public:
  explicit PlanetTomlReader(std::string file) : file_(std::move(file)) {}

  std::size_t errorCount() const { return errors_.size(); }

  void fail(const toml::source_region& where, std::string field, std::string message);

  void remember(const std::string& field, const toml::source_region& where) { where_[field] = where; }
  // A value the file gives through another key (wavelength_m = 1 / frequency_per_m, radius_m =
  // shape.equatorial_radius_m): its errors name the key that is in the file. `inverse`: the file
  // gives the reciprocal, which the message says.
  void rememberAs(const std::string& field, const std::string& keyInFile, const toml::source_region& where,
                  bool inverse = false) {
    where_[field] = where;
    spelledAs_[field] = {keyInFile, inverse};
  }

  // Adds validatePlanetAll's findings at the positions of the values they name.
  void addValidationErrors(std::vector<Error> found);

  // Every error, in file order (then in the order found, for errors at one position).
  std::vector<Error> takeErrors();

  std::optional<double> number(const toml::node& node, const std::string& field);

  std::optional<std::int64_t> integer(const toml::node& node, const std::string& field);

  std::optional<std::string> string(const toml::node& node, const std::string& field);

  // A file path: a non-empty string, relative paths resolved against `directory` (the planet file's
  // folder; "" = the current one), lexically normal. `emptyHint` follows "must not be empty".
  std::optional<std::string> path(const toml::node& node, const std::string& field, const std::string& directory,
                                  std::string_view emptyHint = "");

  // A number (an integer) in [low, high]; outside it the error says "must be in [low, high]".
  std::optional<double> numberIn(const toml::node& node, const std::string& field, double low, double high);
  std::optional<std::int64_t> integerIn(const toml::node& node, const std::string& field, std::int64_t low,
                                        std::int64_t high);

  // [r, g, b], linear; the range [0, 1] is checked by validation.
  std::optional<glm::vec3> colour(const toml::node& node, const std::string& field);

  const toml::table* table(const toml::node& node, const std::string& field, std::string_view how);

  // The elements of an array of tables ([[name]]); reports anything else.
  const toml::array* arrayOfTables(const toml::node& node, const std::string& field);

 private:
  std::string file_;
  std::vector<Error> errors_;
  std::set<std::string> failed_fields_;
  std::map<std::string, toml::source_region> where_;
  struct Spelling {
    std::string keyInFile;
    bool inverse = false;
  };
  std::map<std::string, Spelling> spelledAs_;  // field -> the key in the file that gave it
};

}  // namespace globe
