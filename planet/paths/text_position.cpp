#include "planet/paths/text_position.h"

#include <algorithm>

namespace globe {

TextPosition textPositionOf(std::string_view text, std::size_t byteOffset) {
  byteOffset = std::min(byteOffset, text.size());
  TextPosition p;
  std::size_t lineStart = 0;
  for (std::size_t i = 0; i < byteOffset; ++i) {
    if (text[i] == '\n') {
      ++p.line;
      lineStart = i + 1;
    }
  }
  p.column = static_cast<int>(byteOffset - lineStart) + 1;
  return p;
}

}  // namespace globe
