#include "planet/core/error.h"

namespace globe {

namespace {

// Bytes in a well-formed UTF-8 sequence starting at text[i] (RFC 3629: no overlong forms, no
// surrogates, nothing past U+10FFFF); 0 when there is none.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i) {
  const auto at = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = at(i);
  std::size_t n = 0;
  unsigned char low = 0x80, high = 0xbf;  // the range of the second byte
  if (lead >= 0xc2 && lead <= 0xdf)
    n = 2;
  else if (lead >= 0xe0 && lead <= 0xef)
    n = 3, low = lead == 0xe0 ? 0xa0 : 0x80, high = lead == 0xed ? 0x9f : 0xbf;
  else if (lead >= 0xf0 && lead <= 0xf4)
    n = 4, low = lead == 0xf0 ? 0x90 : 0x80, high = lead == 0xf4 ? 0x8f : 0xbf;
  if (n == 0 || i + n > text.size() || at(i + 1) < low || at(i + 1) > high) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (at(i + k) < 0x80 || at(i + k) > 0xbf) return 0;
  return n;
}

}  // namespace

std::string escapeControlCharacters(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string escaped;
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte >= 0x20 && byte < 0x7f) {
      escaped += text[i++];
    } else if (const std::size_t n = byte >= 0x80 ? utf8SequenceLength(text, i) : 0) {
      escaped += text.substr(i, n);  // a character of another script: kept
      i += n;
    } else {  // a control character or a byte that is not UTF-8: never sent raw to a terminal
      escaped += {'\\', 'x', kHex[byte >> 4], kHex[byte & 15]};
      ++i;
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
