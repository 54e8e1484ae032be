#pragma once
// Line and column of a byte offset in a text: parsers (pugixml, nlohmann-json) report byte offsets,
// and globe's errors name file:line:col.
#include <cstddef>
#include <string_view>
#include <vector>

namespace globe {

struct TextPosition {
  int line = 1;    // 1-based
  int column = 1;  // 1-based, in bytes from the start of the line
};

// The line starts of a text, found once; each position is then a binary search. A reader that
// records a line per keyframe used to rescan the text from its start each time: quadratic (55,000
// KML FlyTos took 158 s).
class LineIndex {
 public:
  explicit LineIndex(std::string_view text);
  // Offsets past the end clamp to the end of the text.
  TextPosition positionOf(std::size_t byteOffset) const;

 private:
  std::vector<std::size_t> lineStarts_;  // byte offset of each line's first byte; [0] = 0
  std::size_t size_ = 0;
};

}  // namespace globe
