#include "planet/paths/czml_path.h"

#include "planet/camera/camera_orientation.h"
#include "planet/paths/text_position.h"

#include <fmt/format.h>
#include <GeographicLib/Geocentric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace globe {

using nlohmann::json;

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Days from 1970-01-01 to y-m-d in the proleptic Gregorian calendar (Hinnant's days_from_civil).
long long daysFromCivil(long long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

// Where each element of the top-level JSON array starts (byte offsets), for error lines.
std::vector<std::size_t> packetOffsets(std::string_view text) {
  std::vector<std::size_t> offsets;
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        inString = false;
      continue;
    }
    if (c == '"') inString = true;
    if (c == '{' || c == '[') {
      if (depth == 1) offsets.push_back(i);
      ++depth;
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return offsets;
}

// One time-tagged property: times in absolute seconds (or none for a constant) and values.
struct Samples {
  std::vector<double> times_s;              // empty for a constant
  std::vector<std::vector<double>> values;  // one per time (or one constant)
};

struct CzmlReader {
  std::string_view text;
  const LineIndex& lines;
  const std::string& file;
  std::size_t packetStart = 0;

  // An error at the first `"key"` of the current packet (its start when not found).
  Error errorAt(std::string_view key, std::string message) const {
    std::size_t at = text.find(fmt::format("\"{}\"", key), packetStart);
    TextPosition p = lines.positionOf(at == std::string_view::npos ? packetStart : at);
    return Error::at(file, p.line, p.column, std::string(key), std::move(message));
  }

  Result<double> epochOf(const json& property, std::string_view name) const {
    if (!property.contains("epoch")) return 0.0;
    const json& e = property["epoch"];
    auto t = e.is_string() ? parseIso8601_s(e.get<std::string>()) : std::nullopt;
    if (!t) return errorAt("epoch", fmt::format("{} epoch must be an ISO 8601 date-time string", name));
    return *t;
  }

  // `array` holds `width` numbers per sample, each preceded by a time, or `width` numbers once.
  Result<Samples> samples(const json& array, std::size_t width, double epoch_s, std::string_view key) const {
    if (!array.is_array()) return errorAt(key, "must be an array of numbers");
    Samples out;
    const std::size_t n = array.size();
    const bool constant = n == width;
    if (!constant && (n == 0 || n % (width + 1) != 0))
      return errorAt(
          key, fmt::format("expected {} numbers, or samples of a time and {} numbers, got {} values", width, width, n));
    const std::size_t stride = constant ? width : width + 1;
    for (std::size_t i = 0; i < n; i += stride) {
      if (!constant) {
        const json& t = array[i];
        std::optional<double> time = t.is_number()   ? std::optional<double>(epoch_s + t.get<double>())
                                     : t.is_string() ? parseIso8601_s(t.get<std::string>())
                                                     : std::nullopt;
        if (!time)
          return errorAt(key, fmt::format("sample {}: time must be seconds or an ISO 8601 string", i / stride));
        if (!out.times_s.empty() && !(*time > out.times_s.back()))
          return errorAt(key, fmt::format("sample {}: times must increase", i / stride));
        out.times_s.push_back(*time);
      }
      std::vector<double> v;
      for (std::size_t j = 0; j < width; ++j) {
        const json& x = array[i + (constant ? 0 : 1) + j];
        if (!x.is_number()) return errorAt(key, fmt::format("sample {}: value {} is not a number", i / stride, j + 1));
        v.push_back(x.get<double>());
      }
      out.values.push_back(std::move(v));
    }
    return out;
  }
};

// Geodetic latitude, longitude (degrees) and height (metres) of every position sample.
Result<Samples> readPosition(const CzmlReader& r, const json& position) {
  if (!position.is_object())
    return r.errorAt("position", "must be an object (time intervals of positions are not supported)");
  if (position.contains("referenceFrame") && position["referenceFrame"] != "FIXED")
    return r.errorAt("referenceFrame", "only the FIXED (Earth-fixed) frame is supported");
  if (position.contains("interpolationAlgorithm")) {
    const json& a = position["interpolationAlgorithm"];
    if (a != "LINEAR" && a != "LAGRANGE" && a != "HERMITE")
      return r.errorAt("interpolationAlgorithm", "must be LINEAR, LAGRANGE or HERMITE");
  }
  auto epoch = r.epochOf(position, "position");
  if (!epoch) return epoch.error();
  for (const char* key : {"cartographicDegrees", "cartographicRadians", "cartesian"}) {
    if (!position.contains(key)) continue;
    auto s = r.samples(position[key], 3, *epoch, key);
    if (!s) return s.error();
    const std::string_view k = key;
    for (std::vector<double>& v : s->values) {
      if (k == "cartesian") {
        double lat, lon, h;
        GeographicLib::Geocentric::WGS84().Reverse(v[0], v[1], v[2], lat, lon, h);
        v = {lat, lon, h};
      } else {
        const double scale = k == "cartographicRadians" ? 1.0 / kDeg : 1.0;
        v = {v[1] * scale, v[0] * scale, v[2]};
      }
      if (std::abs(v[0]) > 90) return r.errorAt(key, "latitude must be within [-90, 90]");
      if (!(v[2] > 0))
        return r.errorAt(key, fmt::format("height {} m: the camera must be above the ellipsoid (> 0 m)", v[2]));
    }
    return s;
  }
  return r.errorAt("position", "needs cartographicDegrees, cartographicRadians or cartesian");
}

Result<Samples> readOrientation(const CzmlReader& r, const json& orientation) {
  if (!orientation.is_object() || !orientation.contains("unitQuaternion"))
    return r.errorAt("orientation", "must be an object with unitQuaternion samples");
  auto epoch = r.epochOf(orientation, "orientation");
  if (!epoch) return epoch.error();
  auto s = r.samples(orientation["unitQuaternion"], 4, *epoch, "unitQuaternion");
  if (!s) return s.error();
  for (const auto& q : s->values)
    if (!(std::hypot(q[0], q[1], q[2]) + std::abs(q[3]) > 0)) return r.errorAt("unitQuaternion", "is zero");
  return s;
}

// Linear in every component between the samples around `t_s` (ends held).
std::vector<double> interpolated(const Samples& s, double t_s) {
  if (s.times_s.empty() || t_s <= s.times_s.front()) return s.values.front();
  if (t_s >= s.times_s.back()) return s.values.back();
  auto it = std::upper_bound(s.times_s.begin(), s.times_s.end(), t_s);
  const std::size_t b = static_cast<std::size_t>(it - s.times_s.begin()), a = b - 1;
  const double f = (t_s - s.times_s[a]) / (s.times_s[b] - s.times_s[a]);
  std::vector<double> v = s.values[a];
  for (std::size_t i = 0; i < v.size(); ++i) v[i] += (s.values[b][i] - v[i]) * f;
  return v;
}

glm::dquat quaternionAt(const Samples& s, double t_s) {
  auto quat = [&](std::size_t i) {
    const auto& q = s.values[i];
    return glm::normalize(glm::dquat(q[3], q[0], q[1], q[2]));
  };
  if (s.times_s.empty() || t_s <= s.times_s.front()) return quat(0);
  if (t_s >= s.times_s.back()) return quat(s.values.size() - 1);
  auto it = std::upper_bound(s.times_s.begin(), s.times_s.end(), t_s);
  const std::size_t b = static_cast<std::size_t>(it - s.times_s.begin()), a = b - 1;
  return glm::slerp(quat(a), quat(b), (t_s - s.times_s[a]) / (s.times_s[b] - s.times_s[a]));
}

// The camera pose of body orientation q (x forward, y left, z up) at geodetic lat/lon.
GeodeticPose poseOf(const std::vector<double>& latLonHeight, const glm::dquat& q) {
  CameraBasis basis;
  basis.forward = glm::normalize(q * glm::dvec3(1, 0, 0));
  basis.right = glm::normalize(-(q * glm::dvec3(0, 1, 0)));
  basis.up = glm::normalize(q * glm::dvec3(0, 0, 1));
  glm::dvec3 hpr = headingPitchRoll_deg(basis, latLonHeight[0], latLonHeight[1]);
  return GeodeticPose{latLonHeight[0], latLonHeight[1], latLonHeight[2], hpr.x, hpr.y, hpr.z};
}

Result<CameraPath> pathFromPacket(const CzmlReader& r, const json& packet) {
  auto position = readPosition(r, packet["position"]);
  if (!position) return position.error();
  if (!packet.contains("orientation"))
    return r.errorAt("position", "this packet has no orientation: globe needs the camera's unitQuaternion");
  auto orientation = readOrientation(r, packet["orientation"]);
  if (!orientation) return orientation.error();
  std::vector<double> times = position->times_s;
  times.insert(times.end(), orientation->times_s.begin(), orientation->times_s.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  if (times.size() < 2)
    return r.errorAt("position", "a camera path needs at least 2 sample times in position or orientation");
  const int line = r.lines.positionOf(r.packetStart).line;
  std::vector<PathKeyframe> keys;
  for (double t : times) {
    GeodeticPose pose = poseOf(interpolated(*position, t), quaternionAt(*orientation, t));
    keys.push_back(PathKeyframe{t - times.front(), pose, line, HeightReference::sphere, false});
  }
  return CameraPath::create(std::move(keys), r.file);
}

// nlohmann's DOM builder, keeping where the first error is: a number beyond double's range (1e400)
// otherwise escapes as an out_of_range exception with no position, and its raw text was printed.
struct PositionedDomParser : nlohmann::detail::json_sax_dom_parser<json> {
  using json_sax_dom_parser::json_sax_dom_parser;
  std::size_t errorAt = 0;              // byte offset of the error
  std::string lastKey, field, message;  // field: the key of an out-of-range number

  bool key(json::string_t& k) {
    lastKey = k;
    return json_sax_dom_parser::key(k);
  }
  template <class Exception>
  bool parse_error(std::size_t byte, const std::string& lastToken, const Exception& e) {
    // nlohmann counts bytes read: one past the offending character, or past the whole number.
    const std::size_t last = byte > 0 ? byte - 1 : 0;
    errorAt = e.id == 406 && last + 1 >= lastToken.size() ? last + 1 - lastToken.size() : last;
    // nlohmann's text is "[json.exception.KIND.ID] parse error at line L, column C: what".
    std::string what = e.what();
    auto colon = what.find(": ", what.find("column"));
    if (e.id == 406) field = lastKey;
    message = e.id == 406                  ? fmt::format("number {} is out of range (beyond a double)", lastToken)
              : colon == std::string::npos ? what.substr(what.find(']') + 2)
                                           : what.substr(colon + 2);
    return false;
  }
};

Result<json> parseJson(std::string_view text, const LineIndex& lines, const std::string& file) {
  json doc;
  PositionedDomParser dom(doc, /*allow_exceptions=*/false);
  if (json::sax_parse(text.begin(), text.end(), &dom)) return doc;
  TextPosition p = lines.positionOf(dom.errorAt);
  return Error::at(file, p.line, p.column, dom.field, "invalid JSON: " + dom.message);
}
}  // namespace

std::optional<double> parseIso8601_s(std::string_view text) {
  std::string s(text);
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, consumed = 0;
  double sec = 0;
  if (std::sscanf(s.c_str(), "%4d-%2d-%2dT%2d:%2d:%lf%n", &y, &mo, &d, &h, &mi, &sec, &consumed) != 6) return {};
  // The day must exist in its month (February 30 was accepted).
  const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
  const int monthDays[] = {31, leap ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (mo < 1 || mo > 12 || d < 1 || d > monthDays[mo - 1] || h > 24 || mi > 59 || !(sec >= 0 && sec < 61)) return {};
  std::string_view zone = text.substr(static_cast<std::size_t>(consumed));
  double offset_s = 0;
  if (zone.size() == 6 && (zone[0] == '+' || zone[0] == '-') && zone[3] == ':') {
    int zh = 0, zm = 0;
    if (std::sscanf(std::string(zone.substr(1)).c_str(), "%2d:%2d", &zh, &zm) != 2) return {};
    if (zh > 14 || zm > 59) return {};  // real offsets are within ±14:00 (+99:99 was accepted)
    offset_s = (zone[0] == '+' ? 1.0 : -1.0) * (zh * 3600.0 + zm * 60.0);
  } else if (zone != "Z") {
    return {};
  }
  double days = static_cast<double>(daysFromCivil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d)));
  return days * 86400.0 + h * 3600.0 + mi * 60.0 + sec - offset_s;
}

Result<CameraPath> parseCzmlPath(std::string_view text, const std::string& fileName) {
  const LineIndex lines(text);
  auto parsed = parseJson(text, lines, fileName);
  if (!parsed) return parsed.error();
  const json& doc = *parsed;
  if (!doc.is_array()) return Error::at(fileName, 1, 1, "", "a CZML document must be a JSON array of packets");
  std::vector<std::size_t> offsets = packetOffsets(text);
  for (std::size_t i = 0; i < doc.size(); ++i) {
    if (!doc[i].is_object() || !doc[i].contains("position")) continue;
    CzmlReader reader{text, lines, fileName, i < offsets.size() ? offsets[i] : 0};
    return pathFromPacket(reader, doc[i]);
  }
  return Error::at(fileName, 1, 1, "position", "no packet has a position (the camera's packet needs one)");
}

}  // namespace globe
