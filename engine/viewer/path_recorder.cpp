#include "engine/viewer/path_recorder.h"

#include "planet/camera/camera_orientation.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>

namespace globe {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

double angleBetween_deg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) / kDeg;
}

// Rotation angle between two poses' orientations (what CameraPath limits per segment).
double turn_deg(const GeodeticPose& a, const GeodeticPose& b) {
  glm::dquat qa = orientationFromBasis(basisFromPose(a)), qb = orientationFromBasis(basisFromPose(b));
  double d = std::min(1.0, std::abs(glm::dot(qa, qb)));
  return 2.0 * std::acos(d) / kDeg;
}

}  // namespace

void PathRecorder::start(const GeodeticPose& pose) {
  recording_ = true;
  time_s_ = 0;
  last_ = pose;
  keys_.clear();
  push(pose);
}

void PathRecorder::push(const GeodeticPose& pose) { keys_.push_back({time_s_, pose, 0}); }

void PathRecorder::advance(double dt_s, const GeodeticPose& pose) {
  if (!recording_ || !(dt_s > 0)) return;
  time_s_ += dt_s;
  last_ = pose;
  const PathKeyframe& previous = keys_.back();
  bool due = time_s_ - previous.time_s >= kInterval_s - 1e-9;
  if (!due) {
    glm::dvec3 from = directionFromLatLon(previous.pose.latitude_deg, previous.pose.longitude_deg);
    glm::dvec3 to = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
    due = angleBetween_deg(from, to) > kMaxArc_deg || turn_deg(previous.pose, pose) > kMaxTurn_deg;
  }
  if (due) push(pose);
}

Result<CameraPath> PathRecorder::stop() {
  recording_ = false;
  if (keys_.empty() || time_s_ <= keys_.back().time_s) {
    if (keys_.size() < 2) return Error::inField("recording", "too short to be a path (no camera time passed)");
  } else {
    push(last_);
  }
  std::vector<PathKeyframe> keys = std::move(keys_);
  keys_.clear();
  return CameraPath::create(std::move(keys));
}

std::string timestampedPathFile(const std::string& directory) {
  std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  std::filesystem::path dir(directory);
  std::string base = std::string("globe-path-") + stamp;
  std::filesystem::path file = dir / (base + ".path");
  std::error_code ec;
  for (int n = 2; std::filesystem::exists(file, ec); ++n) file = dir / (base + "-" + std::to_string(n) + ".path");
  return file.string();
}

}  // namespace globe
