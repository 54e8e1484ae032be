#pragma once
// Errors for bad input data (files, command-line values, camera positions). Bad data returns an
// Error naming where it came from; programmer mistakes are asserts. Nothing here throws.
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace globe {

struct Error {
  std::string file;     // path of the offending file, or "" when the input is not a file
  int line = 0;         // 1-based line, 0 when unknown
  int column = 0;       // 1-based column, 0 when unknown
  std::string field;    // offending field / option / key, "" when not applicable
  std::string message;  // what is wrong, lower case, no trailing period

  // Named constructors: say which parts are known instead of positional "", 0, 0.
  static Error inField(std::string field, std::string message) {
    return {"", 0, 0, std::move(field), std::move(message)};
  }
  static Error inFile(std::string file, std::string message) { return {std::move(file), 0, 0, "", std::move(message)}; }
  static Error inFileField(std::string file, std::string field, std::string message) {
    return {std::move(file), 0, 0, std::move(field), std::move(message)};
  }
  static Error atLine(std::string file, int line, std::string message) {
    return {std::move(file), line, 0, "", std::move(message)};
  }
  static Error at(std::string file, int line, int column, std::string field, std::string message) {
    return {std::move(file), line, column, std::move(field), std::move(message)};
  }

  // "file:line:column: field: message", omitting the parts that are empty or zero. One line.
  std::string format() const;
};

// `text` with every control character (bytes < 0x20 and DEL, newlines too) and every byte that is
// not part of well-formed UTF-8 shown as \xNN: for input text printed to a terminal (planet names,
// keys, messages), which must carry neither escape sequences nor raw bytes. UTF-8 characters stay.
std::string escapeControlCharacters(std::string_view text);

// How many errors of one file a command prints: a hostile file can hold millions.
inline constexpr std::size_t kMaxErrorsShown = 20;

// One formatted line per error, at most `maxShown` of them, then "… and N more" for the rest.
std::vector<std::string> formatErrorList(const std::vector<Error>& errors, std::size_t maxShown = kMaxErrorsShown);

// A value or an Error. Small on purpose: std::expected is C++23. [[nodiscard]]: an ignored
// Result is an ignored error.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::move(value)) {}      // NOLINT(google-explicit-constructor)
  Result(Error error) : v_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() & { return std::get<0>(v_); }
  const T& value() const& { return std::get<0>(v_); }
  T&& value() && { return std::get<0>(std::move(v_)); }
  const Error& error() const { return std::get<1>(v_); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T&& operator*() && { return std::move(*this).value(); }

 private:
  std::variant<T, Error> v_;
};

// For operations that produce no value.
struct Ok {};
using Status = Result<Ok>;

}  // namespace globe
