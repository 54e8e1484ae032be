#include "engine/viewer/input_script.h"
#include "planet/core/input_file.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

namespace globe {

namespace {

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  return s;
}

bool parseFrame(const std::string& text, uint64_t& out) {
  auto r = std::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

bool parseNumber(const std::string& text, double& out) {
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return !text.empty() && end && *end == '\0' && std::isfinite(out);
}

bool parseUpDown(const std::string& text, bool& down) {
  std::string t = upper(text);
  if (t == "DOWN")
    down = true;
  else if (t == "UP")
    down = false;
  else
    return false;
  return true;
}

}  // namespace

int keyCodeFromName(const std::string& name) {
  static const std::map<std::string, int> named = {
      {"ESCAPE", GLFW_KEY_ESCAPE},
      {"ESC", GLFW_KEY_ESCAPE},
      {"SPACE", GLFW_KEY_SPACE},
      {"ENTER", GLFW_KEY_ENTER},
      {"BACKSPACE", GLFW_KEY_BACKSPACE},
      {"TAB", GLFW_KEY_TAB},
      {"LEFT_SHIFT", GLFW_KEY_LEFT_SHIFT},
      {"SHIFT", GLFW_KEY_LEFT_SHIFT},
      {"RIGHT_SHIFT", GLFW_KEY_RIGHT_SHIFT},
      {"LEFT_CONTROL", GLFW_KEY_LEFT_CONTROL},
      {"CONTROL", GLFW_KEY_LEFT_CONTROL},
      {"CTRL", GLFW_KEY_LEFT_CONTROL},
      {"RIGHT_CONTROL", GLFW_KEY_RIGHT_CONTROL},
      {"UP", GLFW_KEY_UP},
      {"DOWN", GLFW_KEY_DOWN},
      {"LEFT", GLFW_KEY_LEFT},
      {"RIGHT", GLFW_KEY_RIGHT},
  };
  std::string n = upper(name);
  if (n.size() == 1 && n[0] >= 'A' && n[0] <= 'Z') return GLFW_KEY_A + (n[0] - 'A');
  if (n.size() == 1 && n[0] >= '0' && n[0] <= '9') return GLFW_KEY_0 + (n[0] - '0');
  if (n.size() >= 2 && n[0] == 'F') {
    int f = 0;
    auto r = std::from_chars(n.data() + 1, n.data() + n.size(), f);
    if (r.ec == std::errc() && r.ptr == n.data() + n.size() && f >= 1 && f <= 25) return GLFW_KEY_F1 + f - 1;
  }
  auto it = named.find(n);
  return it == named.end() ? -1 : it->second;
}

namespace {

// The events of one script line after its frame number (`w`: the line's words): appended to `out`;
// the error message, or empty.
std::string parseEvent(const std::vector<std::string>& w, std::vector<InputEvent>& out) {
  InputEvent e;
  std::string verb = w.size() > 1 ? upper(w[1]) : "";
  if (verb == "KEY") {
    if (w.size() != 4) return "expected 'FRAME KEY NAME down|up'";
    e.code = keyCodeFromName(w[2]);
    if (e.code < 0) return "unknown key '" + w[2] + "'";
    e.type = InputEvent::Type::kKey;
    if (!parseUpDown(w[3], e.down)) return "expected down or up, got '" + w[3] + "'";
  } else if (verb == "MOUSE" && w.size() > 2 && upper(w[2]) == "MOVE") {
    if (w.size() != 5 || !parseNumber(w[3], e.x) || !parseNumber(w[4], e.y))
      return "expected 'FRAME MOUSE MOVE X Y' with X, Y in pixels";
    e.type = InputEvent::Type::kMouseMove;
  } else if (verb == "MOUSE") {
    static const std::map<std::string, int> buttons = {
        {"LEFT", GLFW_MOUSE_BUTTON_LEFT}, {"RIGHT", GLFW_MOUSE_BUTTON_RIGHT}, {"MIDDLE", GLFW_MOUSE_BUTTON_MIDDLE}};
    if (w.size() != 4) return "expected 'FRAME MOUSE MOVE X Y' or 'FRAME MOUSE LEFT|RIGHT|MIDDLE down|up'";
    auto it = buttons.find(upper(w[2]));
    if (it == buttons.end()) return "unknown mouse button '" + w[2] + "'";
    e.type = InputEvent::Type::kMouseButton;
    e.code = it->second;
    if (!parseUpDown(w[3], e.down)) return "expected down or up, got '" + w[3] + "'";
  } else if (verb == "RESIZE") {
    if (w.size() != 4 || !parseNumber(w[2], e.x) || !parseNumber(w[3], e.y) || e.x < 16 || e.y < 16 || e.x > 16384 ||
        e.y > 16384 || e.x != std::floor(e.x) || e.y != std::floor(e.y))
      return "expected 'FRAME RESIZE W H' with whole W, H within [16, 16384] pixels";
    e.type = InputEvent::Type::kResize;
  } else if (verb == "TEXT") {
    // One character event per character, as typing them would send (the go-to line).
    if (w.size() != 3) return "expected 'FRAME TEXT CHARACTERS' (no spaces)";
    for (unsigned char ch : w[2]) out.push_back({InputEvent::Type::kChar, ch, true, 0, 0});
    return "";
  } else if (verb == "WAIT") {
    if (w.size() != 3 || upper(w[2]) != "RELOAD") return "expected 'FRAME WAIT RELOAD'";
    e.type = InputEvent::Type::kWaitReload;
  } else {
    return "unknown event '" + (w.size() > 1 ? w[1] : std::string()) + "' (expected KEY, TEXT, MOUSE, RESIZE or WAIT)";
  }
  out.push_back(e);
  return "";
}

}  // namespace

Result<InputScript> parseInputScript(const std::string& text, const std::string& file) {
  InputScript script;
  std::istringstream in(text);
  std::string line;
  std::vector<InputEvent> events;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty()) continue;
    uint64_t frame = 0;
    if (!parseFrame(w[0], frame)) return Error::atLine(file, lineNo, "expected a frame number, got '" + w[0] + "'");
    events.clear();
    if (std::string why = parseEvent(w, events); !why.empty()) return Error::atLine(file, lineNo, why);
    for (const InputEvent& e : events) script.events.push_back({frame, e});
  }
  std::stable_sort(script.events.begin(), script.events.end(),
                   [](const ScriptedEvent& a, const ScriptedEvent& b) { return a.frame < b.frame; });
  return script;
}

Result<InputScript> loadInputScript(const std::string& path, const std::string& field) {
  Result<std::string> content = readInputFile(path, "input script");
  if (!content) {
    Error e = content.error();
    e.field = field;
    return e;
  }
  return parseInputScript(*content, path);
}

std::vector<InputEvent> InputScript::take(uint64_t frame) {
  std::vector<InputEvent> out;
  while (cursor < events.size() && events[cursor].frame <= frame) out.push_back(events[cursor++].event);
  return out;
}

}  // namespace globe
