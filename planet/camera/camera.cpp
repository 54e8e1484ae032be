#include "planet/camera/camera.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace globe {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

Result<double> parseNumber(const std::string& text, const std::string& field, const char* what) {
  const char* begin = text.c_str();
  char* end = nullptr;
  double v = std::strtod(begin, &end);
  while (end && *end == ' ') ++end;
  if (text.empty() || end == begin || *end != '\0')
    return Error::inField(field, std::string(what) + " '" + text + "' is not a number");
  if (!std::isfinite(v)) return Error::inField(field, std::string(what) + " must be finite");
  return v;
}
}  // namespace

Result<HeightReference> parseHeightReference(std::string_view text, const std::string& field) {
  if (text == "ground") return HeightReference::ground;
  if (text == "sphere" || text == "ellipsoid") return HeightReference::sphere;
  return Error::inField(field, "must be 'ground', 'sphere' or 'ellipsoid', got '" + std::string(text) + "'");
}

Result<GeodeticPose> poseAboveGround(GeodeticPose pose, double groundRadius_m, double referenceRadius_m,
                                     const std::string& field) {
  const double terrain_m = groundRadius_m - referenceRadius_m;  // the ground above the reference surface
  const double above_m = pose.height_m - terrain_m;
  if (!(above_m > 0.0)) {
    return Error::inField(field, fmt::format("height {:g} m above the reference surface is {} the ground there "
                                             "({:.3f} m): the camera must be above it",
                                             pose.height_m, above_m == 0.0 ? "on" : "under", terrain_m));
  }
  pose.height_m = above_m;
  if (auto s = validatePose(pose, field); !s) return s.error();
  return pose;
}

Result<GeodeticPose> parsePose(const std::string& text, const std::string& field, HeightReference reference) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) parts.push_back(part);
  if (!text.empty() && text.back() == ',') parts.push_back("");
  if (parts.size() != 3 && parts.size() != 6)
    return Error::inField(field, "expected LAT,LON,HEIGHT[,HEADING,PITCH,ROLL], got '" + text + "'");
  static const char* names[] = {"latitude", "longitude", "height", "heading", "pitch", "roll"};
  double v[6] = {0, 0, 0, 0, 0, 0};
  for (size_t i = 0; i < parts.size(); ++i) {
    auto r = parseNumber(parts[i], field, names[i]);
    if (!r) return r.error();
    v[i] = *r;
  }
  GeodeticPose pose{v[0], v[1], v[2], v[3], v[4], v[5]};
  if (parts.size() == 3) pose.pitch_deg = std::nan("");  // "look at the horizon", resolved later
  if (reference == HeightReference::ground) {
    if (auto s = validatePose(pose, field); !s) return s.error();
    return pose;
  }
  if (pose.height_m < -kMaxDepthBelowReference_m || pose.height_m > 1e12)
    return Error::inField(field, fmt::format("height must be within [{:g}, 1e12] metres above the reference surface",
                                             -kMaxDepthBelowReference_m));
  GeodeticPose check = pose;
  check.height_m = 1.0;  // the other fields; the height is checked against the ground later
  if (auto s = validatePose(check, field); !s) return s.error();
  return pose;
}

Status validatePose(const GeodeticPose& pose, const std::string& field) {
  if (!std::isfinite(pose.latitude_deg) || std::abs(pose.latitude_deg) > 90)
    return Error::inField(field, "latitude must be within [-90, 90] degrees");
  if (!std::isfinite(pose.longitude_deg)) return Error::inField(field, "longitude must be finite");
  if (!std::isfinite(pose.height_m) || pose.height_m <= 0 || pose.height_m > 1e12)
    return Error::inField(field, "height must be within (0, 1e12] metres above the surface");
  if (!std::isfinite(pose.heading_deg) || !std::isfinite(pose.roll_deg))
    return Error::inField(field, "heading and roll must be finite");
  if (!std::isnan(pose.pitch_deg) && std::abs(pose.pitch_deg) > 90)
    return Error::inField(field, "pitch must be within [-90, 90] degrees");
  return Ok{};
}

namespace {
// Local east, north and up at a position (from its latitude and longitude, so defined at the poles).
glm::dmat3 localFrame(const glm::dvec3& position_m) {
  glm::dvec2 ll = latLonFromPosition(position_m);
  double lat = ll.x * kDeg, lon = ll.y * kDeg;
  glm::dvec3 up{std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
  glm::dvec3 east{-std::sin(lon), std::cos(lon), 0.0};
  return glm::dmat3(east, glm::cross(up, east), up);
}
}  // namespace

glm::dvec3 defaultSunDirection(const glm::dvec3& position_m) {
  const glm::dmat3 frame = localFrame(position_m);
  double towardsEquator = latLonFromPosition(position_m).x >= 0 ? -1.0 : 1.0;
  return glm::normalize(0.5 * frame[0] + 0.5 * towardsEquator * frame[1] + 1.0 * frame[2]);
}

Result<SunAngles> parseSunAngles(const std::string& text, const std::string& field) {
  const size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    return Error::inField(field, "expected AZIMUTH,ELEVATION in degrees, got '" + text + "'");
  auto azimuth = parseNumber(text.substr(0, comma), field, "azimuth");
  if (!azimuth) return azimuth.error();
  auto elevation = parseNumber(text.substr(comma + 1), field, "elevation");
  if (!elevation) return elevation.error();
  SunAngles sun{*azimuth, *elevation};
  if (auto s = validateSunAngles(sun, field); !s) return s.error();
  return sun;
}

Status validateSunAngles(const SunAngles& sun, const std::string& field) {
  if (!std::isfinite(sun.azimuth_deg)) return Error::inField(field, "sun azimuth must be finite");
  if (!std::isfinite(sun.elevation_deg) || std::abs(sun.elevation_deg) > 90)
    return Error::inField(field, "sun elevation must be within [-90, 90] degrees");
  return Ok{};
}

glm::dvec3 sunDirectionAt(const glm::dvec3& position_m, const SunAngles& sun) {
  const glm::dmat3 frame = localFrame(position_m);
  const double az = sun.azimuth_deg * kDeg, el = sun.elevation_deg * kDeg;
  return glm::normalize(std::cos(el) * (std::sin(az) * frame[0] + std::cos(az) * frame[1]) + std::sin(el) * frame[2]);
}

SunAngles sunAnglesAt(const glm::dvec3& position_m, const glm::dvec3& direction) {
  const glm::dmat3 frame = localFrame(position_m);
  const glm::dvec3 d = glm::normalize(direction);
  const double east = glm::dot(d, frame[0]), north = glm::dot(d, frame[1]), up = glm::dot(d, frame[2]);
  double azimuth = std::atan2(east, north) / kDeg;
  if (azimuth < 0) azimuth += 360.0;
  return {azimuth, std::asin(std::clamp(up, -1.0, 1.0)) / kDeg};
}

double horizonPitch_deg(double height_m, double radius_m) {
  // The horizon lies acos(R / (R + h)) below the local horizontal.
  double ratio = radius_m / (radius_m + std::max(height_m, 0.0));
  return -std::acos(std::clamp(ratio, -1.0, 1.0)) / kDeg;
}

glm::dvec3 directionFromLatLon(double latitude_deg, double longitude_deg) {
  double lat = latitude_deg * kDeg, lon = longitude_deg * kDeg;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

glm::dvec2 latLonFromPosition(const glm::dvec3& p) {
  double lon = std::atan2(p.y, p.x) / kDeg;
  double lat = std::atan2(p.z, std::hypot(p.x, p.y)) / kDeg;
  return {lat, lon};
}

Camera cameraFromPose(const GeodeticPose& pose, double groundRadius_m, double sphereRadius_m, double aspect) {
  return cameraFromPose(pose, groundRadius_m, Ellipsoid::sphere(sphereRadius_m), aspect);
}

Camera cameraFromPose(const GeodeticPose& pose, double groundRadius_m, const Ellipsoid& shape, double aspect) {
  Camera cam;
  cam.aspect = aspect;
  // GeographicLib (Ellipsoid::pointAbove): position and the local east/north/up frame.
  glm::dvec3 enu[3];
  cam.position_m = shape.pointAbove(pose.latitude_deg, pose.longitude_deg, groundRadius_m, pose.height_m, &enu);
  const glm::dvec3 east = enu[0], north = enu[1], upLocal = enu[2];

  const double horizonRadius_m = shape.equatorialRadius_m();
  double pitch = std::isnan(pose.pitch_deg) ? horizonPitch_deg(pose.height_m, horizonRadius_m) - 2.0 : pose.pitch_deg;
  pitch = std::clamp(pitch, -90.0, 90.0);
  double h = pose.heading_deg * kDeg, p = pitch * kDeg, r = pose.roll_deg * kDeg;
  glm::dvec3 forward = std::cos(p) * (std::sin(h) * east + std::cos(h) * north) + std::sin(p) * upLocal;
  // Right is defined by the heading alone, so straight-down views keep a stable orientation.
  glm::dvec3 right = std::cos(h) * east - std::sin(h) * north;
  glm::dvec3 up = glm::cross(right, forward);
  // Roll turns right and up about the view direction.
  glm::dvec3 rolledRight = std::cos(r) * right - std::sin(r) * up;
  glm::dvec3 rolledUp = std::sin(r) * right + std::cos(r) * up;
  cam.forward = glm::normalize(forward);
  cam.right = glm::normalize(rolledRight);
  cam.up = glm::normalize(rolledUp);
  // Near plane: a fraction of the height above ground, so 1 cm over the surface still resolves.
  cam.near_m = std::clamp(pose.height_m * 0.25, 1e-4, 100.0);
  return cam;
}

glm::dmat4 Camera::viewFromWorld(const glm::dvec3& origin_m) const {
  glm::dvec3 eye = position_m - origin_m;
  glm::dvec3 back = -forward;
  glm::dmat4 v(1.0);
  v[0][0] = right.x;
  v[1][0] = right.y;
  v[2][0] = right.z;
  v[0][1] = up.x;
  v[1][1] = up.y;
  v[2][1] = up.z;
  v[0][2] = back.x;
  v[1][2] = back.y;
  v[2][2] = back.z;
  v[3][0] = -glm::dot(right, eye);
  v[3][1] = -glm::dot(up, eye);
  v[3][2] = -glm::dot(back, eye);
  return v;
}

glm::dmat4 Camera::projection() const {
  double f = 1.0 / std::tan(verticalFov_rad * 0.5);
  glm::dmat4 p(0.0);
  p[0][0] = f / aspect;
  p[1][1] = -f;      // Vulkan clip space: y points down
  p[3][2] = near_m;  // z_clip = near
  p[2][3] = -1.0;    // w_clip = -z_view
  return p;
}

GeodeticPose standardCameraPose(int index) {
  switch (index) {
    case 0:
      return {20.0, -100.0, 2.0e7, 0, -90, 0};
    case 1:
      return {22.0, -99.0, 1.0e5, 60, -30, 0};
    case 2:
      return {22.0, -98.8, 1.0e4, 60, -15, 0};
    case 3:
      return {22.05, -98.4, 1.0e3, 60, -8, 0};
    default:
      return {22.1, -98.3, 2.0, 60, -2, 0};
  }
}

const char* standardCameraName(int index) {
  static const char* const kNames[kStandardCameraCount] = {"orbit", "100km", "10km", "1km", "2m"};
  return kNames[index < 0 || index >= kStandardCameraCount ? kStandardCameraCount - 1 : index];
}

}  // namespace globe
