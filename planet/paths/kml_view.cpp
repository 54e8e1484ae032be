#include "planet/paths/kml_view.h"

#include "planet/camera/camera_orientation.h"

namespace globe {

std::optional<KmlAltitudeMode> parseKmlAltitudeMode(std::string_view text) {
  // globe's terrain is the sea floor too: below sea level the ground is the bottom of the sea.
  if (text == "clampToGround" || text == "clampToSeaFloor") return KmlAltitudeMode::clampToGround;
  if (text == "relativeToGround" || text == "relativeToSeaFloor") return KmlAltitudeMode::relativeToGround;
  if (text == "absolute") return KmlAltitudeMode::absolute;
  return std::nullopt;
}

ImportedPose poseFromKmlLookAt(const KmlLookAt& view, double sphereRadius_m) {
  const bool clamped = view.altitudeMode == KmlAltitudeMode::clampToGround;
  const double targetAltitude_m = clamped ? 0.0 : view.altitude_m;
  const glm::dvec3 target =
      directionFromLatLon(view.latitude_deg, view.longitude_deg) * (sphereRadius_m + targetAltitude_m);
  // The view at the target: heading as given, pitched down by 90 - tilt. The camera sits `range`
  // behind the target along that view, with the same axes (a LookAt has no roll).
  GeodeticPose atTarget{view.latitude_deg, view.longitude_deg, 1.0, view.heading_deg, view.tilt_deg - 90.0, 0.0};
  CameraBasis basis = basisFromPose(atTarget);
  const glm::dvec3 eye = target - basis.forward * view.range_m;
  glm::dvec2 latLon = latLonFromPosition(eye);
  ImportedPose out;
  out.pose.latitude_deg = latLon.x;
  out.pose.longitude_deg = latLon.y;
  out.pose.height_m = glm::length(eye) - sphereRadius_m;
  glm::dvec3 hpr = headingPitchRoll_deg(basis, latLon.x, latLon.y);
  out.pose.heading_deg = hpr.x;
  out.pose.pitch_deg = hpr.y;
  out.pose.roll_deg = hpr.z;
  out.heightReference =
      view.altitudeMode == KmlAltitudeMode::absolute ? HeightReference::sphere : HeightReference::ground;
  return out;
}

ImportedPose poseFromKmlCamera(const KmlCamera& view) {
  ImportedPose out;
  out.pose.latitude_deg = view.latitude_deg;
  out.pose.longitude_deg = view.longitude_deg;
  out.pose.height_m = view.altitudeMode == KmlAltitudeMode::clampToGround ? kOnGroundHeight_m : view.altitude_m;
  out.pose.heading_deg = view.heading_deg;
  out.pose.pitch_deg = view.tilt_deg - 90.0;
  out.pose.roll_deg = -view.roll_deg;  // KML rolls right-handed about its backward axis: positive is left
  out.heightReference =
      view.altitudeMode == KmlAltitudeMode::absolute ? HeightReference::sphere : HeightReference::ground;
  return out;
}

KmlCamera kmlCameraFromPose(const GeodeticPose& pose, HeightReference reference) {
  KmlCamera c;
  c.longitude_deg = pose.longitude_deg;
  c.latitude_deg = pose.latitude_deg;
  c.altitude_m = pose.height_m;
  c.heading_deg = pose.heading_deg;
  c.tilt_deg = pose.pitch_deg + 90.0;
  c.roll_deg = -pose.roll_deg;
  c.altitudeMode = reference == HeightReference::sphere ? KmlAltitudeMode::absolute : KmlAltitudeMode::relativeToGround;
  return c;
}

}  // namespace globe
