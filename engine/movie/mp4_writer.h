#pragma once
// Encodes frames into an MP4 file through FFmpeg's libraries (libavcodec, libavformat, libswscale):
// H.264 by libx264 when libavcodec has it, else another H.264 encoder, else MPEG-4 part 2.
// Bit-exact flags and one encoder thread keep the output a pure function of the frames.
#include "engine/io/image_io.h"
#include "planet/core/error.h"

#include <memory>
#include <string>

namespace globe {

class Mp4Writer {
 public:
  // Creates `file` (written as MP4 whatever its name, so it may be a temporary). Width and height
  // must be even (4:2:0 chroma); fps > 0.
  static Result<std::unique_ptr<Mp4Writer>> open(const std::string& file, uint32_t width, uint32_t height, int fps);
  ~Mp4Writer();
  Mp4Writer(const Mp4Writer&) = delete;
  Mp4Writer& operator=(const Mp4Writer&) = delete;

  // Appends one frame (linear colour, converted to 8-bit sRGB then YUV 4:2:0); its size must match.
  Status addFrame(const ImageRgba& image);
  // Flushes the encoder and writes the MP4 index. The file is complete only after this.
  Status finish();
  // "libx264 (H.264)", "mpeg4 (MPEG-4 part 2)", ...
  const std::string& encoderDescription() const;

  struct Impl;

 private:
  explicit Mp4Writer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace globe
