#pragma once
// Image files: PNG (8-bit sRGB, through stb) and OpenEXR (half RGB colour and an optional float
// depth channel `Z`). Writes are atomic (temporary file, then rename).
#include "planet/core/error.h"

#include <span>
#include <string>
#include <vector>

namespace globe {

struct ImageRgba {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgba;  // linear, 4 floats per pixel, row 0 at the top
  std::vector<float> z;     // optional per-pixel depth (metres along the view ray), empty if absent
};

// Linear [0,1] -> 8-bit sRGB, the conversion writePng applies.
uint8_t linearToSrgb8(float linear);

Status writePng(const std::string& path, const ImageRgba& image);
// The PNG file's bytes, for outputs written later together (writeFilesAtomically).
Result<std::string> encodePng(const ImageRgba& image);
Status writeExr(const std::string& path, const ImageRgba& image);
// Chooses PNG or EXR from the extension (.png / .exr); anything else is an Error on `field`.
Status writeImage(const std::string& path, const ImageRgba& image, const std::string& field);

// An 8-bit sRGB PNG or JPEG file (stb), as linear floats.
Result<ImageRgba> readImage8(const std::string& path);
Result<ImageRgba> readExr(const std::string& path);

}  // namespace globe
