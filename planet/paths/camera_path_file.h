#pragma once
// Camera path files (.path): line-based text, easy to edit by hand and to report errors on. The
// format, every column with units and ranges, is in docs/camera-paths.md; assets/paths/ has examples.
//
//   # comments start with '#', anywhere on a line; blank lines are ignored
//   t_s  lat_deg  lon_deg  height_m  heading_deg  pitch_deg  roll_deg     <- header, exactly these
//   0    45.0     7.0      800000    0            -90        0            <- one keyframe per line
//   7    45.1     7.2      40        30           -10        0
//
// Nothing throws out of these functions: every problem (unreadable file, missing header, bad or
// non-finite number, missing or extra field, out-of-range value, non-increasing time, fewer than two
// keyframes) is an Error that formats as "file:line: message".
#include "planet/core/error.h"
#include "planet/paths/camera_path.h"

#include <string>
#include <string_view>

namespace globe {

// The header line naming the columns, in order.
inline constexpr std::string_view kCameraPathHeader = "t_s lat_deg lon_deg height_m heading_deg pitch_deg roll_deg";

// Reads and validates a path file: .kml (a Google Earth tour, planet/paths/kml_tour.h) and .czml
// (planet/paths/czml_path.h) by their extension, any other name as a .path file.
Result<CameraPath> loadCameraPath(const std::string& path);

// Same, from text already in memory; `fileName` is the name used in errors.
Result<CameraPath> parseCameraPath(std::string_view text, const std::string& fileName);

// The file text of a path: a comment, the header, and one keyframe per line with every number
// printed as %.17g, so parsing it back gives bit-identical keyframes (including -0).
std::string formatCameraPath(const CameraPath& path);

// The shortest decimal that reads back to the same double (fmt's default: 22.12, not
// 22.120000000000001), and 0 for -0: what a person editing a file expects to see.
std::string shortestNumberText(double v);

// Writes formatCameraPath(path) to `file` atomically (no half-written file on failure).
Status saveCameraPath(const std::string& file, const CameraPath& path);

}  // namespace globe
