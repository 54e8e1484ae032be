#pragma once
// Scripted input for the viewer (tests, demos): a text file of events, each applied at the start
// of a given frame exactly as if it came from the keyboard or mouse. Format (docs/viewer.md):
//
//   # comment               blank lines and '#' comments are ignored
//   FRAME KEY NAME down|up  NAME: A-Z, 0-9, F1-F12, ESCAPE, SPACE, LEFT_SHIFT, RIGHT_SHIFT, ...
//   FRAME MOUSE MOVE X Y    cursor position in window pixels (origin top-left)
//   FRAME MOUSE LEFT|RIGHT|MIDDLE down|up
//   FRAME RESIZE W H        asks the window system for a new window size (pixels)
//   FRAME WAIT RELOAD       holds the frame loop until the planet file changes (live-reload tests)
//
// FRAME is the 0-based frame number.
#include "engine/viewer/input_event.h"
#include "planet/core/error.h"

#include <cstdint>
#include <string>
#include <vector>

namespace globe {

struct ScriptedEvent {
  uint64_t frame = 0;
  InputEvent event;
};

// Events sorted by frame (stable: same-frame events keep file order).
struct InputScript {
  std::vector<ScriptedEvent> events;

  // The events of frame `frame`, assuming frames are asked for in increasing order from `cursor`.
  std::vector<InputEvent> take(uint64_t frame);
  size_t cursor = 0;
};

// Parses script text; errors name `file` and the 1-based line.
Result<InputScript> parseInputScript(const std::string& text, const std::string& file);
Result<InputScript> loadInputScript(const std::string& path, const std::string& field);

// GLFW key code for a script key name (case-insensitive), or -1.
int keyCodeFromName(const std::string& name);

}  // namespace globe
