#include "planet/core/error.h"

namespace globe {

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
  // One line, always: a message built from input text must not smuggle newlines.
  for (char& c : out) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return out;
}

std::vector<std::string> formatErrorList(const std::vector<Error>& errors, std::size_t maxShown) {
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < errors.size() && i < maxShown; ++i) lines.push_back(errors[i].format());
  if (errors.size() > maxShown) lines.push_back("\u2026 and " + std::to_string(errors.size() - maxShown) + " more");
  return lines;
}

}  // namespace globe
