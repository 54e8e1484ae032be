#pragma once
// Google Earth tours (KML gx:Tour) as camera paths, and camera paths as tours.
//
// Reading: the first <gx:Tour> of the file; its <gx:Playlist>'s <gx:FlyTo> (gx:duration,
// gx:flyToMode, a <LookAt> or <Camera>) and <gx:Wait> (gx:duration) become keyframes; other tour
// primitives (gx:AnimatedUpdate, gx:TourControl, gx:SoundCue) do not move the camera and are skipped.
// The path starts at t = 0 at the first FlyTo's view (globe has no "current view" to fly from, so
// that FlyTo's duration is not used); each later FlyTo ends gx:duration seconds after the previous
// primitive, a Wait holds the view for its duration. "bounce" FlyTos (the KML default) start and end
// at rest; a run of "smooth" FlyTos flies through its views and rests only at its ends, as in
// Google Earth. Views: kml_view.h.
//
// Errors are "file:line:col: element: message" (pugixml's byte offsets turned into lines).
#include "planet/core/error.h"
#include "planet/paths/camera_path.h"

#include <string>
#include <string_view>

namespace globe {

Result<CameraPath> parseKmlTour(std::string_view text, const std::string& fileName);

// A KML document with one gx:Tour named `name`: a smooth gx:FlyTo with a <Camera> per keyframe
// (relativeToGround or absolute), and a gx:Wait where the camera holds still between two equal
// keyframes. Numbers are %.17g, so parseKmlTour(formatKmlTour(p)) gives p's keyframes back (times
// shifted to start at 0, tilt = pitch + 90 rounded once).
std::string formatKmlTour(const CameraPath& path, const std::string& name);

}  // namespace globe
