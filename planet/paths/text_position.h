#pragma once
// Line and column of a byte offset in a text: parsers (pugixml, nlohmann-json) report byte offsets,
// and globe's errors name file:line:col.
#include <cstddef>
#include <string_view>

namespace globe {

struct TextPosition {
  int line = 1;    // 1-based
  int column = 1;  // 1-based, in bytes from the start of the line
};

// Offsets past the end clamp to the end of the text.
TextPosition textPositionOf(std::string_view text, std::size_t byteOffset);

}  // namespace globe
