#include "planet/paths/text_position.h"

#include <algorithm>

namespace globe {

LineIndex::LineIndex(std::string_view text) : lineStarts_{0}, size_(text.size()) {
  for (std::size_t i = text.find('\n'); i != std::string_view::npos; i = text.find('\n', i + 1))
    lineStarts_.push_back(i + 1);
}

TextPosition LineIndex::positionOf(std::size_t byteOffset) const {
  byteOffset = std::min(byteOffset, size_);
  // The last line start at or before the offset (lineStarts_[0] = 0, so there is one).
  auto after = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), byteOffset);
  const auto line = static_cast<std::size_t>(after - lineStarts_.begin());
  return TextPosition{static_cast<int>(line), static_cast<int>(byteOffset - lineStarts_[line - 1]) + 1};
}

}  // namespace globe
