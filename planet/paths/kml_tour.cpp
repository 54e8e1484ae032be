#include "planet/paths/kml_tour.h"

#include "planet/paths/kml_view.h"
#include "planet/paths/text_position.h"

#include <fmt/format.h>
#include <pugixml.hpp>

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <vector>

namespace globe {

namespace {

// Element names without their namespace prefix: files write gx:FlyTo, kml:Camera or FlyTo.
std::string_view localName(const pugi::xml_node& node) {
  std::string_view name = node.name();
  auto colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

pugi::xml_node childNamed(const pugi::xml_node& parent, std::string_view name) {
  for (pugi::xml_node c : parent.children())
    if (c.type() == pugi::node_element && localName(c) == name) return c;
  return {};
}

// The first gx:Tour in document order. pugixml's find_node walks the tree iteratively (parent and
// sibling links): a recursive search overflowed the stack on a file nested 1e5 elements deep.
pugi::xml_node findTour(const pugi::xml_node& document) {
  return document.find_node(
      [](const pugi::xml_node& n) { return n.type() == pugi::node_element && localName(n) == "Tour"; });
}

// An element's text: all its text and CDATA children joined. A comment splits the text into two
// children (`22<!-- c -->.1` is 22.1 to XML); the first alone read 22.
std::string textOf(const pugi::xml_node& node) {
  std::string text;
  for (pugi::xml_node c : node.children())
    if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) text += c.value();
  return text;
}

std::string_view trimmed(std::string_view s) {
  const char* blanks = " \t\r\n";
  auto b = s.find_first_not_of(blanks);
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(blanks) - b + 1);
}

struct KmlReader {
  const LineIndex& lines;  // indexed once: every keyframe records its line
  const std::string& file;

  TextPosition positionOf(const pugi::xml_node& node) const {
    return lines.positionOf(static_cast<std::size_t>(std::max<std::ptrdiff_t>(node.offset_debug(), 0)));
  }
  Error errorAt(const pugi::xml_node& node, std::string message) const {
    TextPosition p = positionOf(node);
    return Error::at(file, p.line, p.column, node ? node.name() : "", std::move(message));
  }
  int lineOf(const pugi::xml_node& node) const { return positionOf(node).line; }

  // Reads the number in child `name` of `parent` into `out`; leaves `out` (the KML default) when
  // there is no such child.
  std::optional<Error> read(const pugi::xml_node& parent, std::string_view name, double& out) const {
    pugi::xml_node node = childNamed(parent, name);
    if (!node) return std::nullopt;
    const std::string text = textOf(node);
    std::string_view s = trimmed(text);
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    double v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
      return errorAt(node, fmt::format("'{}' is not a finite number", trimmed(text)));
    out = v;
    return std::nullopt;
  }
  // Several fields of one element, in order; the first error.
  std::optional<Error> readAll(const pugi::xml_node& parent,
                               std::initializer_list<std::pair<std::string_view, double*>> fields) const {
    for (const auto& [name, out] : fields)
      if (auto e = read(parent, name, *out)) return e;
    return std::nullopt;
  }

  // altitudeMode or gx:altitudeMode (KML 2.2 and Google's extension). Both may be given; when they
  // disagree the view is ambiguous and refused (it was resolved silently by whichever came first).
  Result<KmlAltitudeMode> altitudeMode(const pugi::xml_node& view) const {
    std::optional<KmlAltitudeMode> found;
    pugi::xml_node first;
    for (pugi::xml_node node : view.children()) {
      if (node.type() != pugi::node_element || localName(node) != "altitudeMode") continue;
      const std::string text = textOf(node);
      auto mode = parseKmlAltitudeMode(trimmed(text));
      if (!mode)
        return errorAt(node, fmt::format("unknown altitude mode '{}' (expected clampToGround, relativeToGround or "
                                         "absolute)",
                                         trimmed(text)));
      if (found && *mode != *found)
        return errorAt(node, fmt::format("'{}' contradicts {} '{}' on line {}", trimmed(text), first.name(),
                                         trimmed(textOf(first)), lineOf(first)));
      if (!found) found = *mode, first = node;
    }
    return found.value_or(KmlAltitudeMode::clampToGround);  // the KML default
  }
};

Result<ImportedPose> readLookAt(const KmlReader& r, const pugi::xml_node& v) {
  KmlLookAt look;
  if (auto e = r.readAll(v, {{"longitude", &look.longitude_deg},
                             {"latitude", &look.latitude_deg},
                             {"altitude", &look.altitude_m},
                             {"range", &look.range_m},
                             {"tilt", &look.tilt_deg},
                             {"heading", &look.heading_deg}}))
    return *e;
  auto mode = r.altitudeMode(v);
  if (!mode) return mode.error();
  look.altitudeMode = *mode;
  if (std::abs(look.latitude_deg) > 90) return r.errorAt(childNamed(v, "latitude"), "must be within [-90, 90]");
  if (look.tilt_deg < 0 || look.tilt_deg > 90) return r.errorAt(childNamed(v, "tilt"), "must be within [0, 90]");
  if (look.range_m < 0) return r.errorAt(childNamed(v, "range"), "must be >= 0 metres");
  ImportedPose pose = poseFromKmlLookAt(look);
  if (!(pose.pose.height_m > 0)) return r.errorAt(v, "the camera of this LookAt is not above the ground");
  return pose;
}

Result<ImportedPose> readCamera(const KmlReader& r, const pugi::xml_node& v) {
  KmlCamera cam;
  if (auto e = r.readAll(v, {{"longitude", &cam.longitude_deg},
                             {"latitude", &cam.latitude_deg},
                             {"altitude", &cam.altitude_m},
                             {"heading", &cam.heading_deg},
                             {"tilt", &cam.tilt_deg},
                             {"roll", &cam.roll_deg}}))
    return *e;
  auto mode = r.altitudeMode(v);
  if (!mode) return mode.error();
  cam.altitudeMode = *mode;
  if (std::abs(cam.latitude_deg) > 90) return r.errorAt(childNamed(v, "latitude"), "must be within [-90, 90]");
  if (cam.tilt_deg < 0 || cam.tilt_deg > 180) return r.errorAt(childNamed(v, "tilt"), "must be within [0, 180]");
  if (cam.altitudeMode != KmlAltitudeMode::clampToGround && !(cam.altitude_m > 0))
    return r.errorAt(childNamed(v, "altitude"),
                     cam.altitudeMode == KmlAltitudeMode::absolute
                         ? "must be > 0 metres: globe cameras stay above sea level in absolute mode"
                         : "must be > 0 metres above the ground");
  return poseFromKmlCamera(cam);
}

Result<ImportedPose> readView(const KmlReader& r, const pugi::xml_node& flyTo) {
  if (pugi::xml_node v = childNamed(flyTo, "LookAt")) return readLookAt(r, v);
  if (pugi::xml_node v = childNamed(flyTo, "Camera")) return readCamera(r, v);
  return r.errorAt(flyTo, "has no LookAt or Camera");
}

// Builds the keyframes of a playlist: times, poses, and where the camera rests.
Result<std::vector<PathKeyframe>> readPlaylist(const KmlReader& r, const pugi::xml_node& playlist) {
  std::vector<PathKeyframe> keys;
  double t_s = 0;
  for (pugi::xml_node item : playlist.children()) {
    if (item.type() != pugi::node_element) continue;
    const std::string_view kind = localName(item);
    if (kind != "FlyTo" && kind != "Wait") continue;
    double duration_s = 0;
    if (auto e = r.read(item, "duration", duration_s)) return *e;
    if (duration_s < 0) return r.errorAt(childNamed(item, "duration"), "must be >= 0 seconds");
    if (kind == "Wait") {
      if (keys.empty() || duration_s == 0) continue;  // nothing to hold yet, or no time to hold it
      t_s += duration_s;
      PathKeyframe hold = keys.back();
      hold.time_s = t_s;
      hold.line = r.lineOf(item);
      keys.back().stop = true;  // a smooth flight into a Wait ends at rest
      hold.stop = true;
      keys.push_back(hold);
      continue;
    }
    auto viewResult = readView(r, item);
    if (!viewResult) return viewResult.error();
    const ImportedPose& view = *viewResult;
    const std::string modeText = textOf(childNamed(item, "flyToMode"));
    std::string_view mode = trimmed(modeText);
    if (!mode.empty() && mode != "bounce" && mode != "smooth")
      return r.errorAt(childNamed(item, "flyToMode"), fmt::format("'{}' is not bounce or smooth", mode));
    const bool bounce = mode != "smooth";
    if (!keys.empty()) {
      if (duration_s == 0) return r.errorAt(item, "a FlyTo after the first needs a gx:duration > 0 seconds");
      t_s += duration_s;
      if (bounce) keys.back().stop = true;
    }
    keys.push_back(PathKeyframe{t_s, view.pose, r.lineOf(item), view.heightReference, bounce});
  }
  if (!keys.empty()) {
    keys.front().stop = true;  // a tour starts and ends at rest
    keys.back().stop = true;
  }
  return keys;
}

}  // namespace

Result<CameraPath> parseKmlTour(std::string_view text, const std::string& fileName) {
  pugi::xml_document doc;
  pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size());
  const LineIndex lines(text);
  if (!parsed) {
    TextPosition p = lines.positionOf(static_cast<std::size_t>(std::max<std::ptrdiff_t>(parsed.offset, 0)));
    return Error::at(fileName, p.line, p.column, "", fmt::format("invalid XML: {}", parsed.description()));
  }
  KmlReader reader{lines, fileName};
  pugi::xml_node tour = findTour(doc);
  if (!tour) return Error::at(fileName, 1, 0, "gx:Tour", "no tour in this KML file (expected a gx:Tour element)");
  pugi::xml_node playlist = childNamed(tour, "Playlist");
  if (!playlist) return reader.errorAt(tour, "has no gx:Playlist");
  auto keys = readPlaylist(reader, playlist);
  if (!keys) return keys.error();
  if (keys->size() < 2)
    return reader.errorAt(
        playlist, fmt::format("a camera path needs at least 2 views (gx:FlyTo or gx:Wait), found {}", keys->size()));
  return CameraPath::create(std::move(*keys), fileName);
}

namespace {
std::string number17(double v) { return fmt::format("{:.17g}", v); }

void addCamera(pugi::xml_node flyTo, const PathKeyframe& key) {
  KmlCamera c = kmlCameraFromPose(key.pose, key.heightReference);
  pugi::xml_node cam = flyTo.append_child("Camera");
  auto field = [&](const char* name, double v) { cam.append_child(name).text().set(number17(v).c_str()); };
  field("longitude", c.longitude_deg);
  field("latitude", c.latitude_deg);
  field("altitude", c.altitude_m);
  field("heading", c.heading_deg);
  field("tilt", c.tilt_deg);
  field("roll", c.roll_deg);
  cam.append_child("altitudeMode")
      .text()
      .set(c.altitudeMode == KmlAltitudeMode::absolute ? "absolute" : "relativeToGround");
}

bool sameView(const PathKeyframe& a, const PathKeyframe& b) {
  const GeodeticPose &p = a.pose, &q = b.pose;
  return p.latitude_deg == q.latitude_deg && p.longitude_deg == q.longitude_deg && p.height_m == q.height_m &&
         p.heading_deg == q.heading_deg && p.pitch_deg == q.pitch_deg && p.roll_deg == q.roll_deg &&
         a.heightReference == b.heightReference;
}
}  // namespace

std::string formatKmlTour(const CameraPath& path, const std::string& name) {
  pugi::xml_document doc;
  pugi::xml_node decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  pugi::xml_node kml = doc.append_child("kml");
  kml.append_attribute("xmlns") = "http://www.opengis.net/kml/2.2";
  kml.append_attribute("xmlns:gx") = "http://www.google.com/kml/ext/2.2";
  pugi::xml_node document = kml.append_child("Document");
  document.append_child("name").text().set(name.c_str());
  document.append_child(pugi::node_comment)
      .set_value(" exported by `globe path export`; heights are above the ground (relativeToGround) or sea level ");
  pugi::xml_node tour = document.append_child("gx:Tour");
  tour.append_child("name").text().set(name.c_str());
  pugi::xml_node playlist = tour.append_child("gx:Playlist");
  const auto& keys = path.keyframes();
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const double duration_s = i == 0 ? 0.0 : keys[i].time_s - keys[i - 1].time_s;
    if (i > 0 && sameView(keys[i], keys[i - 1])) {
      playlist.append_child("gx:Wait").append_child("gx:duration").text().set(number17(duration_s).c_str());
      continue;
    }
    pugi::xml_node flyTo = playlist.append_child("gx:FlyTo");
    flyTo.append_child("gx:duration").text().set(number17(duration_s).c_str());
    // Both ends at rest is a bounce FlyTo; anything else flies through smoothly.
    const bool bounce = i > 0 && keys[i].stop && keys[i - 1].stop;
    flyTo.append_child("gx:flyToMode").text().set(bounce ? "bounce" : "smooth");
    addCamera(flyTo, keys[i]);
  }
  std::ostringstream out;
  doc.save(out, "  ");
  return out.str();
}

}  // namespace globe
