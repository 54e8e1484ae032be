#pragma once
// CZML (Cesium) documents as camera paths: the first packet with a `position` and an `orientation`
// is the camera.
//
//  - position: `cartographicDegrees` / `cartographicRadians` [t, lon, lat, height, ...] (height above
//    the WGS84 ellipsoid -> metres above the planet's sphere, HeightReference::sphere) or `cartesian`
//    [t, x, y, z, ...] (Earth-fixed metres, converted to WGS84 latitude/longitude/height by
//    GeographicLib); a constant [lon, lat, h] / [x, y, z] without times; `epoch` (ISO 8601) with
//    sample times in seconds after it, or ISO 8601 strings as sample times; referenceFrame FIXED.
//  - orientation: `unitQuaternion` [t, x, y, z, w, ...] or a constant [x, y, z, w], rotating the
//    body axes (x forward, y left, z up: Cesium's model axes) into the Earth-fixed frame.
// Every sample time becomes a keyframe (the union of the position and orientation times; the other
// property is interpolated linearly / by slerp there), so the camera passes exactly through every
// sample. Between samples globe's own spline flies (camera_path.h), whatever
// `interpolationAlgorithm` (LINEAR, LAGRANGE, HERMITE) says. The path's t = 0 is the first sample.
//
// Errors are "file:line:col: field: message"; JSON syntax errors come from nlohmann-json's byte
// offsets, field errors point at the field's key in the packet.
#include "planet/core/error.h"
#include "planet/paths/camera_path.h"

#include <optional>
#include <string>
#include <string_view>

namespace globe {

Result<CameraPath> parseCzmlPath(std::string_view text, const std::string& fileName);

// Seconds since 1970-01-01T00:00:00Z of an ISO 8601 date-time ("2012-08-04T16:00:00Z",
// fractional seconds and +hh:mm offsets allowed); nullopt when it is not one.
std::optional<double> parseIso8601_s(std::string_view text);

}  // namespace globe
