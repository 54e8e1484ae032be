// Fuzz target: the viewer's input scripts (engine/viewer/input_script.h).
#include "engine/viewer/input_script.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const globe::Result<globe::InputScript> script = globe::parseInputScript(text, "fuzz.txt");
  if (script.ok()) {
    globe::InputScript events = script.value();
    for (uint64_t frame = 0; frame < 4; ++frame) (void)events.take(frame);
  }
  return 0;
}
