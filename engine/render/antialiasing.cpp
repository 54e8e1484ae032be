#include "engine/render/antialiasing.h"

namespace globe {

Result<Antialiasing> parseAntialiasing(const std::string& text, const std::string& field) {
  for (Antialiasing aa : {Antialiasing::kNone, Antialiasing::kFxaa, Antialiasing::kMsaa4})
    if (text == antialiasingName(aa)) return aa;
  return Error::inField(field, "unknown anti-aliasing '" + text + "' (none, fxaa, msaa4)");
}

const char* antialiasingName(Antialiasing aa) {
  switch (aa) {
    case Antialiasing::kFxaa:
      return "fxaa";
    case Antialiasing::kMsaa4:
      return "msaa4";
    case Antialiasing::kNone:
      break;
  }
  return "none";
}

VkSampleCountFlagBits sampleCount(Antialiasing aa) {
  return aa == Antialiasing::kMsaa4 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
}

}  // namespace globe
