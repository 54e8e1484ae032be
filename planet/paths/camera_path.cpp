#include "planet/paths/camera_path.h"

#include "planet/camera/camera_orientation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace globe {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
// Below this angle (radians) slerp falls back to a normalised lerp: sin(x)/sin(theta) would divide
// by zero at 0, and the lerp's error (~theta^3) is far below double resolution there.
constexpr double kTinyAngle_rad = 1e-9;

// Angle between unit vectors (radians), accurate near 0 and pi unlike acos(dot).
template <class V>
double angleBetween(const V& a, const V& b) {
  return 2.0 * std::atan2(glm::length(a - b), glm::length(a + b));
}

// Spherical linear interpolation between unit vectors (3-D directions or 4-D quaternions). No sign
// flip: callers choose the quaternion signs once, so the path never jumps mid-segment.
template <class V>
V slerpUnit(const V& a, const V& b, double s) {
  double theta = angleBetween(a, b);
  if (theta < kTinyAngle_rad) return glm::normalize(a + (b - a) * s);
  double inv = 1.0 / std::sin(theta);
  return a * (std::sin((1.0 - s) * theta) * inv) + b * (std::sin(s * theta) * inv);
}

// Tangent vector at unit p pointing along the great circle to unit q, of length = arc (radians).
glm::dvec3 logMap(const glm::dvec3& p, const glm::dvec3& q) {
  glm::dvec3 v = q - p * glm::dot(p, q);
  double len = glm::length(v);
  if (len == 0.0) return glm::dvec3(0.0);
  return v * (angleBetween(p, q) / len);
}

// The point reached from unit p by walking along tangent v for |v| radians.
glm::dvec3 expMap(const glm::dvec3& p, const glm::dvec3& v) {
  double theta = glm::length(v);
  if (theta == 0.0) return p;
  return glm::normalize(p * std::cos(theta) + v * (std::sin(theta) / theta));
}

glm::dvec4 toVec4(const glm::dquat& q) { return {q.x, q.y, q.z, q.w}; }
glm::dquat toQuat(const glm::dvec4& v) { return glm::dquat(v.w, glm::dvec3(v.x, v.y, v.z)); }

// The smallest rotation taking unit a to unit b (a != -b; segments are limited well below 180 deg).
glm::dquat transport(const glm::dvec3& a, const glm::dvec3& b) {
  return glm::normalize(glm::dquat(1.0 + glm::dot(a, b), glm::cross(a, b)));
}

// Shared tangent at a keyframe from the velocities of the segments before and after it: the
// three-point (parabola) derivative, limited to 3x the slower side (Fritsch-Carlson) so that a
// stationary neighbour stops the camera there and the curve cannot overshoot.
template <class V>
V limitedTangent(const V& before, double dtBefore, const V& after, double dtAfter) {
  V m = (before * dtAfter + after * dtBefore) / (dtBefore + dtAfter);
  double cap = 3.0 * std::min(glm::length(before), glm::length(after));
  double len = glm::length(m);
  if (len > cap) m = len > 0.0 ? m * (cap / len) : m;
  return m;
}

double limitedSlope(double before, double dtBefore, double after, double dtAfter) {
  // Scalar: also flat at a local extremum, which is what keeps the cubic monotone.
  if (before == 0.0 || after == 0.0 || (before > 0.0) != (after > 0.0)) return 0.0;
  double m = (before * dtAfter + after * dtBefore) / (dtBefore + dtAfter);
  double cap = 3.0 * std::min(std::abs(before), std::abs(after));
  return std::clamp(m, -cap, cap);
}

Error keyError(const std::string& file, const PathKeyframe& k, std::size_t index, std::string message) {
  return Error::at(file, k.line, 0, k.line > 0 ? "" : fmt::format("keyframe {}", index + 1), std::move(message));
}

// Range checks with the file's column names, so a message points at the value to edit.
std::string poseProblem(const PathKeyframe& k) {
  const GeodeticPose& p = k.pose;
  if (!std::isfinite(k.time_s)) return "t_s must be finite";
  if (std::abs(k.time_s) > CameraPath::kMaxTime_s)
    return fmt::format("t_s must be within [-{0:.0f}, {0:.0f}] seconds", CameraPath::kMaxTime_s);
  if (!std::isfinite(p.latitude_deg)) return "lat_deg must be finite";
  if (std::abs(p.latitude_deg) > 90.0) return "lat_deg must be within [-90, 90]";
  if (!std::isfinite(p.longitude_deg)) return "lon_deg must be finite";
  if (std::abs(p.longitude_deg) > CameraPath::kMaxLongitude_deg)
    return fmt::format("lon_deg must be within [-{0:g}, {0:g}]", CameraPath::kMaxLongitude_deg);
  if (!std::isfinite(p.height_m)) return "height_m must be finite";
  if (p.height_m <= 0.0 || p.height_m > 1e12)
    return k.heightReference == HeightReference::sphere ? "height_m must be within (0, 1e12] metres above the sphere"
                                                        : "height_m must be within (0, 1e12] metres above the ground";
  if (!std::isfinite(p.heading_deg)) return "heading_deg must be finite";
  if (!std::isfinite(p.pitch_deg)) return "pitch_deg must be finite";
  if (std::abs(p.pitch_deg) > 90.0) return "pitch_deg must be within [-90, 90]";
  if (!std::isfinite(p.roll_deg)) return "roll_deg must be finite";
  return "";
}
}  // namespace

Result<CameraPath> CameraPath::create(std::vector<PathKeyframe> keyframes, const std::string& file) {
  if (keyframes.size() < 2) {
    int line = keyframes.empty() ? 0 : keyframes.back().line;
    return Error::atLine(file, line,
                         fmt::format("a camera path needs at least 2 keyframes, found {}", keyframes.size()));
  }
  CameraPath path;
  if (Status s = path.prepareKeys(keyframes, file); !s) return s.error();
  if (const double span_s = keyframes.back().time_s - keyframes.front().time_s; span_s > kMaxDuration_s)
    return Error::atLine(
        file, keyframes.back().line,
        fmt::format("the path lasts {:.0f} s, more than the limit of {:.0f} s", span_s, kMaxDuration_s));
  path.computeTangents(keyframes);
  path.keys_ = std::move(keyframes);
  return path;
}

Status CameraPath::prepareKeys(const std::vector<PathKeyframe>& keyframes, const std::string& file) {
  prepared_.resize(keyframes.size());
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    const PathKeyframe& k = keyframes[i];
    if (std::string problem = poseProblem(k); !problem.empty()) return keyError(file, k, i, problem);
    if (i > 0 && !(k.time_s > keyframes[i - 1].time_s))
      return keyError(file, k, i,
                      fmt::format("t_s must increase: {} is not after the previous keyframe's {}", k.time_s,
                                  keyframes[i - 1].time_s));
    Key& key = prepared_[i];
    key.direction = directionFromLatLon(k.pose.latitude_deg, k.pose.longitude_deg);
    key.logHeight = std::log(k.pose.height_m);
    key.orientation = orientationFromBasis(basisFromPose(k.pose));
    key.sphereWeight = k.heightReference == HeightReference::sphere ? 1.0 : 0.0;
    if (i == 0) continue;
    const Key& prev = prepared_[i - 1];
    double arc_deg = angleBetween(prev.direction, key.direction) / kDeg;
    if (arc_deg > kMaxSegmentArc_deg)
      return keyError(file, k, i,
                      fmt::format("keyframe is {:.1f} degrees of arc from the previous one (at most {:g}); "
                                  "add keyframes between them",
                                  arc_deg, kMaxSegmentArc_deg));
    // Choose this quaternion's sign so it agrees with the previous one carried here: then every
    // segment turns the short way round, consistently from start to end.
    glm::dquat carried = transport(prev.direction, key.direction) * prev.orientation;
    if (glm::dot(carried, key.orientation) < 0.0) key.orientation = -key.orientation;
    double turn_deg = 2.0 * angleBetween(toVec4(carried), toVec4(key.orientation)) / kDeg;
    if (turn_deg > kMaxSegmentTurn_deg)
      return keyError(file, k, i,
                      fmt::format("the camera turns by {:.1f} degrees since the previous keyframe (at most "
                                  "{:g}); add keyframes between them",
                                  turn_deg, kMaxSegmentTurn_deg));
  }
  return Ok{};
}

void CameraPath::computeTangents(const std::vector<PathKeyframe>& keyframes) {
  const std::size_t n = keyframes.size();
  auto dt = [&](std::size_t i) { return keyframes[i + 1].time_s - keyframes[i].time_s; };
  auto chordVelocity = [&](std::size_t i) {  // segment i, on the sphere at its start, 1/s
    return logMap(prepared_[i].direction, prepared_[i + 1].direction) / dt(i);
  };
  auto chordSlope = [&](std::size_t i) { return (prepared_[i + 1].logHeight - prepared_[i].logHeight) / dt(i); };
  for (std::size_t i = 0; i < n; ++i) {
    Key& key = prepared_[i];
    if (i == 0) {
      key.directionTangent = chordVelocity(0);
      key.logHeightSlope = chordSlope(0);
    } else if (i == n - 1) {
      key.directionTangent = -logMap(key.direction, prepared_[i - 1].direction) / dt(i - 1);
      key.logHeightSlope = chordSlope(i - 1);
    } else {
      glm::dvec3 before = -logMap(key.direction, prepared_[i - 1].direction) / dt(i - 1);
      key.directionTangent = limitedTangent(before, dt(i - 1), chordVelocity(i), dt(i));
      key.logHeightSlope = limitedSlope(chordSlope(i - 1), dt(i - 1), chordSlope(i), dt(i));
    }
    if (keyframes[i].stop) {
      key.directionTangent = glm::dvec3(0.0);
      key.logHeightSlope = 0.0;
    }
  }
}

std::size_t CameraPath::segmentOf(double t_s) const {
  auto it =
      std::upper_bound(keys_.begin(), keys_.end(), t_s, [](double t, const PathKeyframe& k) { return t < k.time_s; });
  std::size_t after = static_cast<std::size_t>(it - keys_.begin());
  return std::clamp<std::size_t>(after, 1, keys_.size() - 1) - 1;
}

int CameraPath::keyframeAt(double t_s) const {
  auto it =
      std::lower_bound(keys_.begin(), keys_.end(), t_s, [](const PathKeyframe& k, double t) { return k.time_s < t; });
  if (it == keys_.end() || it->time_s != t_s) return -1;
  return static_cast<int>(it - keys_.begin());
}

glm::dvec3 CameraPath::directionAt(double t_s) const {
  t_s = std::clamp(t_s, startTime_s(), endTime_s());
  if (int k = keyframeAt(t_s); k >= 0) return prepared_[static_cast<std::size_t>(k)].direction;
  std::size_t i = segmentOf(t_s);
  const Key& a = prepared_[i];
  const Key& b = prepared_[i + 1];
  double dt = keys_[i + 1].time_s - keys_[i].time_s;
  double s = (t_s - keys_[i].time_s) / dt;
  // Cubic Bezier on the sphere: inner control points one third of a tangent step from the ends,
  // so the curve leaves a with velocity a.directionTangent and reaches b with b.directionTangent.
  glm::dvec3 p0 = a.direction, p3 = b.direction;
  glm::dvec3 p1 = expMap(p0, a.directionTangent * (dt / 3.0));
  glm::dvec3 p2 = expMap(p3, b.directionTangent * (-dt / 3.0));
  glm::dvec3 q0 = slerpUnit(p0, p1, s), q1 = slerpUnit(p1, p2, s), q2 = slerpUnit(p2, p3, s);
  glm::dvec3 r0 = slerpUnit(q0, q1, s), r1 = slerpUnit(q1, q2, s);
  return glm::normalize(slerpUnit(r0, r1, s));
}

double CameraPath::heightAt(double t_s) const {
  t_s = std::clamp(t_s, startTime_s(), endTime_s());
  if (int k = keyframeAt(t_s); k >= 0) return keys_[static_cast<std::size_t>(k)].pose.height_m;
  std::size_t i = segmentOf(t_s);
  const Key& a = prepared_[i];
  const Key& b = prepared_[i + 1];
  double dt = keys_[i + 1].time_s - keys_[i].time_s;
  double s = (t_s - keys_[i].time_s) / dt;
  // Cubic Hermite basis on ln(height).
  double s2 = s * s, s3 = s2 * s;
  double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  double logHeight = h00 * a.logHeight + h10 * dt * a.logHeightSlope + h01 * b.logHeight + h11 * dt * b.logHeightSlope;
  return std::exp(logHeight);
}

glm::dquat CameraPath::orientationAt(double t_s) const {
  t_s = std::clamp(t_s, startTime_s(), endTime_s());
  if (int k = keyframeAt(t_s); k >= 0) return prepared_[static_cast<std::size_t>(k)].orientation;
  std::size_t i = segmentOf(t_s);
  const Key& a = prepared_[i];
  const Key& b = prepared_[i + 1];
  double s = (t_s - keys_[i].time_s) / (keys_[i + 1].time_s - keys_[i].time_s);
  glm::dvec3 here = directionAt(t_s);
  // Carry both keyframe orientations to where the camera is, then blend: the blend happens in one
  // local frame, so keyframes level with the ground give a level camera in between.
  glm::dquat qa = transport(a.direction, here) * a.orientation;
  glm::dquat qb = transport(b.direction, here) * b.orientation;
  return glm::normalize(toQuat(slerpUnit(toVec4(qa), toVec4(qb), s)));
}

GeodeticPose CameraPath::poseAt(double t_s) const {
  t_s = std::clamp(t_s, startTime_s(), endTime_s());
  if (int k = keyframeAt(t_s); k >= 0) return keys_[static_cast<std::size_t>(k)].pose;
  glm::dvec2 latLon = latLonFromPosition(directionAt(t_s));
  GeodeticPose pose;
  pose.latitude_deg = latLon.x;
  pose.longitude_deg = latLon.y <= -180.0 ? latLon.y + 360.0 : latLon.y;
  pose.height_m = heightAt(t_s);
  glm::dvec3 hpr =
      headingPitchRoll_deg(basisFromOrientation(orientationAt(t_s)), pose.latitude_deg, pose.longitude_deg);
  pose.heading_deg = hpr.x;
  pose.pitch_deg = hpr.y;
  pose.roll_deg = hpr.z;
  return pose;
}

double CameraPath::sphereWeightAt(double t_s) const {
  t_s = std::clamp(t_s, startTime_s(), endTime_s());
  std::size_t i = segmentOf(t_s);
  double wa = prepared_[i].sphereWeight, wb = prepared_[i + 1].sphereWeight;
  if (wa == wb) return wa;
  // Smoothstep: the reference radius changes with zero rate at both keyframes (C1 position).
  double s = (t_s - keys_[i].time_s) / (keys_[i + 1].time_s - keys_[i].time_s);
  double blend = s * s * (3.0 - 2.0 * s);
  return wa + (wb - wa) * blend;
}

double CameraPath::referenceRadiusAt(double t_s, const GroundRadiusFn& groundRadius, double sphereRadius_m) const {
  double w = sphereWeightAt(t_s);
  if (w == 1.0) return sphereRadius_m;
  double ground = groundRadius(directionAt(t_s));
  return w == 0.0 ? ground : ground + w * (sphereRadius_m - ground);
}

namespace {

// direction * (reference + height) on a sphere; on an ellipsoid the same through GeographicLib.
glm::dvec3 pointAbove(const glm::dvec3& direction, double referenceRadius_m, double height_m, const Ellipsoid& shape) {
  if (shape.isSphere()) return direction * (referenceRadius_m + height_m);
  const glm::dvec2 latLon = latLonFromPosition(direction);  // geodetic: the direction is the normal
  return shape.pointAbove(latLon.x, latLon.y, referenceRadius_m, height_m);
}

}  // namespace

glm::dvec3 CameraPath::positionAt(double t_s, const GroundRadiusFn& groundRadius, double sphereRadius_m,
                                  const Ellipsoid& shape) const {
  return pointAbove(directionAt(t_s), referenceRadiusAt(t_s, groundRadius, sphereRadius_m), heightAt(t_s), shape);
}

glm::dvec3 CameraPath::positionAt(double t_s, const GroundRadiusFn& groundRadius, const Ellipsoid& shape) const {
  glm::dvec3 d = directionAt(t_s);
  return pointAbove(d, groundRadius(d), heightAt(t_s), shape);
}

Camera CameraPath::cameraAt(double t_s, double sphereRadius_m, double aspect, const GroundRadiusFn& groundRadius,
                            const Ellipsoid& shape) const {
  const double reference = referenceRadiusAt(t_s, groundRadius, sphereRadius_m);
  if (shape.isSphere()) return cameraFromPose(poseAt(t_s), reference, sphereRadius_m, aspect);
  return cameraFromPose(poseAt(t_s), reference, shape, aspect);
}

}  // namespace globe
