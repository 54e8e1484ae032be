#pragma once
// The viewer's bookmarks (M saves the view, 1-9 go back to it) and its "go to" text (G): places as
// the `--at` option writes them, so a bookmark line pastes into `globe view --at` or `globe render
// --at`. No GPU.
#include "planet/camera/camera.h"
#include "planet/core/error.h"

#include <optional>
#include <string>
#include <vector>

namespace globe {

struct Bookmark {
  GeodeticPose pose;  // height above the ground
  std::string name;
};

// One bookmark a line: "LAT,LON,HEIGHT,HEADING,PITCH,ROLL NAME..." (degrees, metres above the
// ground; NAME optional, the rest of the line); blank lines and everything after '#' are ignored.
// A missing file is an empty list; an unreadable one or a bad line is an Error naming the file,
// the line and the field.
Result<std::vector<Bookmark>> loadBookmarks(const std::string& path);
Result<std::vector<Bookmark>> parseBookmarks(const std::string& text, const std::string& file);
// The file's text: a comment, then one line a bookmark, numbers in their shortest round-trip form.
std::string formatBookmarks(const std::vector<Bookmark>& bookmarks);
// Writes the file atomically, making its directory when missing.
Status saveBookmarks(const std::string& path, const std::vector<Bookmark>& bookmarks);
// $XDG_CONFIG_HOME/globe/bookmarks.txt, else $HOME/.config/globe/bookmarks.txt, else
// ./globe-bookmarks.txt.
std::string defaultBookmarksPath();

// "LAT,LON[,HEIGHT[,HEADING,PITCH,ROLL]]" typed after G: what is left out is taken from `current`
// (height above the ground, then heading/pitch/roll). Errors name the field "go to".
Result<GeodeticPose> parseGoTo(const std::string& text, const GeodeticPose& current);

}  // namespace globe
