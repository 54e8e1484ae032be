#include "planet/core/error.h"

namespace globe {

std::string escapeControlCharacters(std::string_view text) {
  std::string escaped;
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      escaped += {'\\', 'x', kHex[byte >> 4], kHex[byte & 15]};
    } else {
      escaped += c;
    }
  }
  return escaped;
}

std::string Error::format() const {
  std::string out;
  if (!file.empty()) {
    out += file;
    if (line > 0) {
      out += ':' + std::to_string(line);
      if (column > 0) out += ':' + std::to_string(column);
    }
    out += ": ";
  }
  if (!field.empty()) out += field + ": ";
  out += message;
  // One line of plain text, always: a message built from input text (a planet name, a key) must not
  // smuggle newlines or terminal escape sequences.
  return escapeControlCharacters(out);
}

std::vector<std::string> formatErrorList(const std::vector<Error>& errors, std::size_t maxShown) {
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < errors.size() && i < maxShown; ++i) lines.push_back(errors[i].format());
  if (errors.size() > maxShown) lines.push_back("\u2026 and " + std::to_string(errors.size() - maxShown) + " more");
  return lines;
}

}  // namespace globe
