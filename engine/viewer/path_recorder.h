#pragma once
// Records the viewer's flight as a camera path (planet/paths/camera_path.h) that `globe bench --path`
// replays: a keyframe at the start, then one every kInterval_s of camera time (the time the fly
// camera advanced by, so a scripted run at 1/60 s per frame records the same times on any machine),
// and one at the stop. Keyframes come sooner when the camera turned or travelled far since the
// last one, so no segment exceeds CameraPath's arc and turn limits. Plain data; no GPU.
#include "planet/camera/camera.h"
#include "planet/core/error.h"
#include "planet/paths/camera_path.h"

#include <string>
#include <vector>

namespace globe {

class PathRecorder {
 public:
  static constexpr double kInterval_s = 0.25;   // keyframe spacing in camera time
  static constexpr double kMaxTurn_deg = 60.0;  // earlier keyframe when the view turned more
  static constexpr double kMaxArc_deg = 30.0;   // ... or the camera moved this far round the planet

  // Starts a recording at time 0 with `pose` (the camera's pose now).
  void start(const GeodeticPose& pose);
  bool recording() const { return recording_; }
  // The camera advanced by dt_s seconds and now has `pose`.
  void advance(double dt_s, const GeodeticPose& pose);
  // Ends the recording (the last pose is the final keyframe). An Error when it is too short to be
  // a path (no time passed) or the keyframes are not a valid path.
  Result<CameraPath> stop();

  double elapsed_s() const { return time_s_; }
  size_t keyframeCount() const { return keys_.size(); }

 private:
  void push(const GeodeticPose& pose);

  bool recording_ = false;
  double time_s_ = 0;
  GeodeticPose last_;  // pose of the latest advance()
  std::vector<PathKeyframe> keys_;
};

// "globe-path-YYYYmmdd-HHMMSS.path" (local time) in `directory`; "-2", "-3" ... are added before
// the extension when the name is taken.
std::string timestampedPathFile(const std::string& directory);

}  // namespace globe
