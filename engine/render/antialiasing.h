#pragma once
// Anti-aliasing of the scene target (docs/rendering.md, "Anti-aliasing"): none; FXAA, a post-process
// on the finished colour (depth untouched); or MSAA x4 — four coverage and depth samples per pixel,
// the fragment shader run once per pixel, resolved to the one-sample images read back or presented.
#include "planet/core/error.h"

#include <vulkan/vulkan.h>

#include <string>

namespace globe {

enum class Antialiasing { kNone, kFxaa, kMsaa4 };

// "none", "fxaa" or "msaa4"; anything else is an Error naming `field`.
Result<Antialiasing> parseAntialiasing(const std::string& text, const std::string& field);
const char* antialiasingName(Antialiasing aa);
// Samples per pixel of the colour and depth attachments and of every pipeline drawing into them.
VkSampleCountFlagBits sampleCount(Antialiasing aa);

}  // namespace globe
