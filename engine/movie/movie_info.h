#pragma once
// What a movie file holds, read back with libavformat (tests and `globe movie`'s summary).
#include "planet/core/error.h"

#include <cstdint>
#include <string>

namespace globe {

struct MovieInfo {
  uint32_t width = 0, height = 0;
  int64_t frames = 0;       // video packets counted in the file
  double duration_s = 0;    // of the video stream
  double frameRate_hz = 0;  // average
  std::string codec;        // "h264", "mpeg4", ...
};

Result<MovieInfo> readMovieInfo(const std::string& file);

}  // namespace globe
