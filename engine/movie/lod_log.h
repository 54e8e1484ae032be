#pragma once
// The LOD log of a movie sequence: what the terrain's LOD ranges had learned after each frame
// (LodRanges::Observations), one line per frame in DIR/lod-log.txt. The ranges only grow with the
// nodes seen, so a frame depends on every frame before it; a resumed sequence restores the state an
// uninterrupted run had before its first missing frame, and its frames come out bit-identical.
#include "planet/core/error.h"
#include "planet/lod/lod_ranges.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace globe {

inline constexpr const char* kLodLogName = "lod-log.txt";

class LodLog {
 public:
  // Reads DIR/lod-log.txt when there is one. A line cut short (a run killed while appending) or
  // otherwise malformed is skipped: its frame is replayed if needed. Errors: unreadable file.
  static Result<LodLog> open(const std::string& directory);

  // The state after `frame`, when logged.
  const LodRanges::Observations* after(uint64_t frame) const;
  // The latest frame before `frame` whose state is logged.
  std::optional<uint64_t> latestBefore(uint64_t frame) const;
  // Logs the state after `frame` (appended and flushed; a frame already logged is not repeated).
  Status record(uint64_t frame, const LodRanges::Observations& state);

 private:
  std::string file_;
  std::map<uint64_t, LodRanges::Observations> entries_;
  bool cutShort_ = false;  // the file ends in a partial line
};

}  // namespace globe
