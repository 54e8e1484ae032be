#include "planet/paths/camera_path_file.h"
#include "planet/core/input_file.h"

#include "planet/core/atomic_file.h"
#include "planet/paths/czml_path.h"
#include "planet/paths/kml_tour.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <optional>
#include <vector>

namespace globe {

namespace {
// Columns a header may add after the fixed seven (docs/camera-paths.md): what height_m is measured
// from, where the camera comes to rest, and where the sun stands in the keyframe's sky (both or
// neither).
constexpr std::array<std::string_view, 4> kOptionalColumns = {"height_ref", "stop", "sun_azimuth_deg",
                                                              "sun_elevation_deg"};
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

// Which optional columns a file's header adds after the seven fixed ones, in their order.
struct OptionalColumns {
  std::vector<std::string_view> names;  // each of kOptionalColumns at most once
};

Result<OptionalColumns> parseHeader(const std::vector<std::string_view>& fields, const std::string& file, int line) {
  // The header names the columns so a reader of the file needs no documentation to edit it;
  // requiring it exactly also catches files that are not camera paths at all.
  bool fixedOk = fields.size() >= kColumns.size();
  for (std::size_t i = 0; fixedOk && i < kColumns.size(); ++i) fixedOk = fields[i] == kColumns[i];
  if (!fixedOk)
    return Error::atLine(file, line,
                         fmt::format("expected the header '{}', got '{}'", kCameraPathHeader, joined(fields)));
  OptionalColumns columns;
  for (std::size_t i = kColumns.size(); i < fields.size(); ++i) {
    bool known = std::find(kOptionalColumns.begin(), kOptionalColumns.end(), fields[i]) != kOptionalColumns.end();
    bool repeated = std::find(columns.names.begin(), columns.names.end(), fields[i]) != columns.names.end();
    if (!known || repeated)
      return Error::atLine(file, line,
                           fmt::format("{} column '{}' in the header (after the seven fixed columns only height_ref, "
                                       "stop, sun_azimuth_deg and sun_elevation_deg may follow, once each)",
                                       repeated ? "repeated" : "unknown", fields[i]));
    columns.names.push_back(fields[i]);
  }
  auto has = [&](std::string_view name) {
    return std::find(columns.names.begin(), columns.names.end(), name) != columns.names.end();
  };
  if (has("sun_azimuth_deg") != has("sun_elevation_deg"))
    return Error::atLine(file, line, "sun_azimuth_deg and sun_elevation_deg go together: give both columns or neither");
  return columns;
}

// Sets the optional column `name` of `key` from its text.
Status parseOptionalField(std::string_view name, std::string_view text, PathKeyframe& key, const std::string& file,
                          int line) {
  if (name == "height_ref") {
    if (text != "ground" && text != "sphere")
      return Error::atLine(file, line, fmt::format("height_ref must be 'ground' or 'sphere', got '{}'", text));
    key.heightReference = text == "sphere" ? HeightReference::sphere : HeightReference::ground;
  } else if (name == "stop") {
    if (text != "0" && text != "1")
      return Error::atLine(file, line, fmt::format("stop must be 0 or 1, got '{}'", text));
    key.stop = text == "1";
  } else {
    auto number = parseNumber(text, name, file, line);
    if (!number) return number.error();
    key.sun = key.sun.value_or(SunAngles{});
    (name == "sun_azimuth_deg" ? key.sun->azimuth_deg : key.sun->elevation_deg) = *number;
    if (name == "sun_elevation_deg" && std::abs(*number) > 90.0)
      return Error::atLine(file, line, fmt::format("sun_elevation_deg must be within [-90, 90], got '{}'", text));
  }
  return Ok{};
}

Result<PathKeyframe> parseKeyframe(const std::vector<std::string_view>& fields, const OptionalColumns& optional,
                                   const std::string& file, int line) {
  const std::size_t expected = kColumns.size() + optional.names.size();
  auto columnName = [&](std::size_t i) {
    return i < kColumns.size() ? kColumns[i] : optional.names[i - kColumns.size()];
  };
  if (fields.size() < expected)
    return Error::atLine(file, line,
                         fmt::format("missing field {} (expected {} fields, found {})", columnName(fields.size()),
                                     expected, fields.size()));
  if (fields.size() > expected)
    return Error::atLine(file, line, fmt::format("too many fields (expected {}, found {})", expected, fields.size()));
  std::array<double, 7> v{};
  for (std::size_t i = 0; i < kColumns.size(); ++i) {
    auto number = parseNumber(fields[i], kColumns[i], file, line);
    if (!number) return number.error();
    v[i] = *number;
  }
  PathKeyframe key{v[0], GeodeticPose{v[1], v[2], v[3], v[4], v[5], v[6]}, line};
  for (std::size_t i = kColumns.size(); i < expected; ++i)
    if (auto s = parseOptionalField(columnName(i), fields[i], key, file, line); !s) return s.error();
  return key;
}
}  // namespace

Result<CameraPath> parseCameraPath(std::string_view text, const std::string& fileName) {
  std::vector<PathKeyframe> keyframes;
  std::optional<OptionalColumns> header;
  int lineNumber = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    std::string_view line = text.substr(pos, eol == std::string_view::npos ? std::string_view::npos : eol - pos);
    pos = eol == std::string_view::npos ? text.size() : eol + 1;
    ++lineNumber;
    std::vector<std::string_view> fields = fieldsOf(line);
    if (fields.empty()) continue;
    if (!header) {
      auto parsed = parseHeader(fields, fileName, lineNumber);
      if (!parsed) return parsed.error();
      header = *parsed;
      continue;
    }
    auto key = parseKeyframe(fields, *header, fileName, lineNumber);
    if (!key) return key.error();
    keyframes.push_back(*key);
  }
  const int lastLine = std::max(lineNumber, 1);
  if (!header)
    return Error::atLine(fileName, lastLine,
                         fmt::format("empty camera path: expected the header '{}'", kCameraPathHeader));
  if (keyframes.size() < 2)
    return Error::atLine(fileName, lastLine,
                         fmt::format("a camera path needs at least 2 keyframes, found {}", keyframes.size()));
  return CameraPath::create(std::move(keyframes), fileName);
}

Result<CameraPath> loadCameraPath(const std::string& path) {
  Result<std::string> content = readInputFile(path, "camera path file");
  if (!content) return content.error();
  // One place that knows every camera path format, so each command taking --path reads them all.
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".kml") return parseKmlTour(*content, path);
  if (extension == ".czml") return parseCzmlPath(*content, path);
  return parseCameraPath(*content, path);
}

std::string shortestNumberText(double v) { return fmt::format("{}", v == 0.0 ? 0.0 : v); }

std::string formatCameraPath(const CameraPath& path) {
  // The optional columns only when a keyframe needs them, so ground-only paths keep the seven.
  bool anySphere = false, anyStop = false, anySun = false;
  for (const PathKeyframe& k : path.keyframes()) {
    anySphere = anySphere || k.heightReference == HeightReference::sphere;
    anyStop = anyStop || k.stop;
    anySun = anySun || k.sun.has_value();
  }
  std::string out = "# globe camera path (format: docs/camera-paths.md)\n";
  out += kCameraPathHeader;
  out += anySphere ? " height_ref" : "";
  out += anyStop ? " stop" : "";
  out += anySun ? " sun_azimuth_deg sun_elevation_deg" : "";
  out += '\n';
  for (const PathKeyframe& k : path.keyframes()) {
    const GeodeticPose& p = k.pose;
    for (double v : {k.time_s, p.latitude_deg, p.longitude_deg, p.height_m, p.heading_deg, p.pitch_deg, p.roll_deg})
      out += shortestNumberText(v) + ' ';
    out.pop_back();
    if (anySphere) out += k.heightReference == HeightReference::sphere ? " sphere" : " ground";
    if (anyStop) out += k.stop ? " 1" : " 0";
    // A keyframe without a sun in a path where others have one (built in memory): 0, 45.
    if (anySun) {
      const SunAngles sun = k.sun.value_or(SunAngles{0.0, 45.0});
      out += ' ' + shortestNumberText(sun.azimuth_deg) + ' ' + shortestNumberText(sun.elevation_deg);
    }
    out += '\n';
  }
  return out;
}

Status saveCameraPath(const std::string& file, const CameraPath& path) {
  return writeFileAtomically(file, formatCameraPath(path), "camera path");
}

}  // namespace globe
