#pragma once
// One input event of the windowed viewer, from GLFW or from a test script: the same stream, so
// scripted runs exercise exactly the code that real keyboard and mouse input does.
#include <cstdint>

namespace globe {

struct InputEvent {
  enum class Type : uint8_t {
    kKey,          // `code` is a GLFW_KEY_* value
    kMouseButton,  // `code` is a GLFW_MOUSE_BUTTON_* value
    kMouseMove,    // cursor position (x, y) in window pixels, origin top-left
    kResize,       // request a window size (x, y) in pixels (scripts only)
    kWaitReload,   // hold the frame loop until the planet file changes (scripts only: live-reload tests)
    kChar,         // a typed character: `code` is its Unicode code point (the go-to line)
  };
  Type type = Type::kKey;
  int code = 0;
  bool down = false;  // Key / MouseButton: pressed (true) or released (false)
  double x = 0;
  double y = 0;
};

}  // namespace globe
