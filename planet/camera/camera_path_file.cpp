#include "planet/camera/camera_path_file.h"

#include "planet/core/atomic_file.h"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace globe {

namespace {
constexpr std::array<std::string_view, 7> kColumns = {"t_s",         "lat_deg",   "lon_deg", "height_m",
                                                      "heading_deg", "pitch_deg", "roll_deg"};

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Whitespace-separated fields of a line, with any '#' comment removed.
std::vector<std::string_view> fieldsOf(std::string_view line) {
  if (auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isBlank(line[i])) ++i;
    std::size_t start = i;
    while (i < line.size() && !isBlank(line[i])) ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

// A decimal number, locale-independent (from_chars), the whole field or nothing.
Result<double> parseNumber(std::string_view text, std::string_view column, const std::string& file, int line) {
  double v = 0;
  // from_chars does not take a leading '+', which people do write.
  std::string_view digits = text.size() > 1 && text[0] == '+' && text[1] != '-' ? text.substr(1) : text;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (ec == std::errc::result_out_of_range)
    return Error::atLine(file, line, fmt::format("{} '{}' is out of range", column, text));
  if (ec != std::errc() || end != digits.data() + digits.size())
    return Error::atLine(file, line, fmt::format("{} '{}' is not a number", column, text));
  if (!std::isfinite(v)) return Error::atLine(file, line, fmt::format("{} must be finite, got '{}'", column, text));
  return v;
}

std::string joined(const std::vector<std::string_view>& fields) {
  std::string s;
  for (auto f : fields) s += (s.empty() ? "" : " ") + std::string(f);
  return s;
}
}  // namespace

Result<CameraPath> parseCameraPath(std::string_view text, const std::string& fileName) {
  std::vector<PathKeyframe> keyframes;
  bool sawHeader = false;
  int lineNumber = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    std::string_view line = text.substr(pos, eol == std::string_view::npos ? std::string_view::npos : eol - pos);
    pos = eol == std::string_view::npos ? text.size() : eol + 1;
    ++lineNumber;
    std::vector<std::string_view> fields = fieldsOf(line);
    if (fields.empty()) continue;
    if (!sawHeader) {
      // The header names the columns so a reader of the file needs no documentation to edit it;
      // requiring it exactly also catches files that are not camera paths at all.
      if (joined(fields) != kCameraPathHeader)
        return Error::atLine(fileName, lineNumber,
                             fmt::format("expected the header '{}', got '{}'", kCameraPathHeader, joined(fields)));
      sawHeader = true;
      continue;
    }
    if (fields.size() < kColumns.size())
      return Error::atLine(fileName, lineNumber,
                           fmt::format("missing field {} (expected {} fields, found {})", kColumns[fields.size()],
                                       kColumns.size(), fields.size()));
    if (fields.size() > kColumns.size())
      return Error::atLine(fileName, lineNumber,
                           fmt::format("too many fields (expected {}, found {})", kColumns.size(), fields.size()));
    std::array<double, 7> v{};
    for (std::size_t i = 0; i < kColumns.size(); ++i) {
      auto number = parseNumber(fields[i], kColumns[i], fileName, lineNumber);
      if (!number) return number.error();
      v[i] = *number;
    }
    keyframes.push_back(PathKeyframe{v[0], GeodeticPose{v[1], v[2], v[3], v[4], v[5], v[6]}, lineNumber});
  }
  const int lastLine = std::max(lineNumber, 1);
  if (!sawHeader)
    return Error::atLine(fileName, lastLine,
                         fmt::format("empty camera path: expected the header '{}'", kCameraPathHeader));
  if (keyframes.size() < 2)
    return Error::atLine(fileName, lastLine,
                         fmt::format("a camera path needs at least 2 keyframes, found {}", keyframes.size()));
  return CameraPath::create(std::move(keyframes), fileName);
}

Result<CameraPath> loadCameraPath(const std::string& path) {
  // A directory opens as a stream that reads as empty: say what it is instead of "empty path".
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return Error::inFile(path, "cannot read camera path file: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error::inFile(path, "cannot open camera path file");
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) return Error::inFile(path, "cannot read camera path file");
  return parseCameraPath(content.str(), path);
}

std::string formatCameraPath(const CameraPath& path) {
  std::string out = "# globe camera path (format: docs/camera-paths.md)\n";
  out += kCameraPathHeader;
  out += '\n';
  for (const PathKeyframe& k : path.keyframes()) {
    const GeodeticPose& p = k.pose;
    // %.17g: enough digits that every double reads back to itself.
    out += fmt::format("{:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}\n", k.time_s, p.latitude_deg,
                       p.longitude_deg, p.height_m, p.heading_deg, p.pitch_deg, p.roll_deg);
  }
  return out;
}

Status saveCameraPath(const std::string& file, const CameraPath& path) {
  return writeFileAtomically(file, formatCameraPath(path), "camera path");
}

}  // namespace globe
