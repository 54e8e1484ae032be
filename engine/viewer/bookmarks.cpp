#include "engine/viewer/bookmarks.h"

#include "planet/core/atomic_file.h"
#include "planet/core/input_file.h"
#include "planet/paths/camera_path_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace globe {

namespace {

// `decimals` places at most, trailing zeros dropped, never "-0": a flown pose holds 20.000744638056165
// and -1.85e-13, awkward to read or edit.
std::string rounded(double v, int decimals) {
  std::string text = fmt::format("{:.{}f}", v, decimals);
  if (text.find('.') != std::string::npos) {
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
  }
  return text == "-0" ? "0" : text;
}

// Latitude/longitude to 1e-7 degree (1 cm), height to 1 mm, angles to 0.001 degree.
std::string poseText(const GeodeticPose& p) {
  return rounded(p.latitude_deg, 7) + "," + rounded(p.longitude_deg, 7) + "," + rounded(p.height_m, 3) + "," +
         rounded(p.heading_deg, 3) + "," + rounded(p.pitch_deg, 3) + "," + rounded(p.roll_deg, 3);
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

Result<std::vector<Bookmark>> parseBookmarks(const std::string& text, const std::string& file) {
  std::vector<Bookmark> out;
  std::istringstream in(text);
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    line = trim(line);
    if (line.empty()) continue;
    const auto space = line.find_first_of(" \t");
    const std::string place = line.substr(0, space);
    if (std::count(place.begin(), place.end(), ',') != 5)
      return Error::at(file, lineNo, 0, "place", "expected LAT,LON,HEIGHT,HEADING,PITCH,ROLL, got '" + place + "'");
    auto pose = parsePose(place, "place");
    if (!pose) return Error::at(file, lineNo, 0, pose.error().field, pose.error().message);
    out.push_back({*pose, space == std::string::npos ? "" : trim(line.substr(space))});
  }
  return out;
}

Result<std::vector<Bookmark>> loadBookmarks(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::vector<Bookmark>{};
  Result<std::string> text = readInputFile(path, "bookmarks");
  if (!text) return text.error();
  return parseBookmarks(*text, path);
}

std::string formatBookmarks(const std::vector<Bookmark>& bookmarks) {
  std::string out =
      "# globe view bookmarks: LAT,LON,HEIGHT,HEADING,PITCH,ROLL (degrees, metres above the ground) NAME\n";
  for (const Bookmark& b : bookmarks) out += poseText(b.pose) + (b.name.empty() ? "" : " " + b.name) + "\n";
  return out;
}

Status saveBookmarks(const std::string& path, const std::vector<Bookmark>& bookmarks) {
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!dir.empty() && !std::filesystem::exists(dir, ec)) {
    std::filesystem::create_directories(dir, ec);
    if (ec) return Error::inField("bookmarks", "cannot make directory '" + dir.string() + "': " + ec.message());
  }
  return writeFileAtomically(path, formatBookmarks(bookmarks), "bookmarks");
}

std::string defaultBookmarksPath() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
    return (std::filesystem::path(xdg) / "globe" / "bookmarks.txt").string();
  if (const char* home = std::getenv("HOME"); home && *home)
    return (std::filesystem::path(home) / ".config" / "globe" / "bookmarks.txt").string();
  return "globe-bookmarks.txt";
}

Result<GeodeticPose> parseGoTo(const std::string& typed, const GeodeticPose& current) {
  std::string text = trim(typed);
  const auto commas = std::count(text.begin(), text.end(), ',');
  if (commas == 1) text += "," + shortestNumberText(current.height_m);
  if (commas <= 2)
    text += "," + shortestNumberText(current.heading_deg) + "," + shortestNumberText(current.pitch_deg) + "," +
            shortestNumberText(current.roll_deg);
  if (commas == 0 || commas == 3 || commas == 4 || commas > 5)
    return Error::inField("go to", "expected LAT,LON[,HEIGHT[,HEADING,PITCH,ROLL]], got '" + trim(typed) + "'");
  return parsePose(text, "go to");
}

}  // namespace globe
