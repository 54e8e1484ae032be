#pragma once
// Where the viewer can jump: G opens a "go to" line that takes the typed text (Backspace edits,
// Enter goes, Esc cancels), M bookmarks the view into the bookmarks file, 1-9 go to bookmark N
// (engine/viewer/bookmarks.h). No GPU.
#include "engine/viewer/bookmarks.h"
#include "engine/viewer/input_event.h"

#include <optional>
#include <string>
#include <vector>

namespace globe {

class ViewerPlaces {
 public:
  static constexpr std::size_t kMaxTyped = 96;  // characters on the go-to line

  ViewerPlaces(std::string bookmarksPath, std::vector<Bookmark> bookmarks);

  // True when the event is this class's: a G, M or 1-9 press, or any key press or character while
  // the go-to line is open (typing "46" there jumps to no bookmark, Esc there does not quit).
  // Releases are never taken, so keys held before G do not stick.
  bool handle(const InputEvent& event);
  // What the keys asked for since the last call, against the camera's `current` pose: the pose to go
  // to, if any. `message` gets what to show (where it went, a bookmark saved, an error).
  std::optional<GeodeticPose> apply(const GeodeticPose& current, std::string& message);

  bool pending() const { return markWanted_ || submitted_ || wanted_; }  // apply() has something to do
  bool typing() const { return typing_; }
  const std::string& typed() const { return typed_; }
  const std::vector<Bookmark>& bookmarks() const { return bookmarks_; }
  const std::string& bookmarksPath() const { return path_; }

 private:
  bool handleTyping(const InputEvent& event);
  std::optional<GeodeticPose> goTo(const GeodeticPose& current, std::string& message);
  void mark(const GeodeticPose& current, std::string& message);

  std::string path_;
  std::vector<Bookmark> bookmarks_;
  bool typing_ = false;
  std::string typed_;
  std::optional<std::string> submitted_;  // the go-to line at Enter
  std::optional<std::size_t> wanted_;     // bookmark index asked for
  bool markWanted_ = false;
};

}  // namespace globe
