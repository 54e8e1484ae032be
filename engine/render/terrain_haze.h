#pragma once
// The analytic haze's constants of one frame (shaders/include/terrain_haze.glsl): the terrain
// pipelines without the atmosphere's light (the `sky` detail) put the ground through the air with
// them, per vertex, without the atmosphere's tables (docs/rendering.md, "Haze").
#include "planet/geometry/ellipsoid.h"
#include "shaders/include/atmosphere_layout.h"
#include "shaders/include/terrain_layout.h"

#include <glm/vec3.hpp>

namespace globe {

// Where the atmosphere's model (a sphere of `radius_m`, the planet's radius) sees the camera at
// `camera_m` (planet-fixed): on a sphere the camera itself; on an ellipsoid the point at the camera's
// height above the planet's reference surface along its geodetic vertical, so that the sky, the
// aerial perspective table and the haze's sunlight are those of the camera's own height (the
// geocentric radius put the ground 10.7 km under the model's bottom at 45 degrees on WGS84). The
// terrain's camera-relative vectors are added to it unchanged: within the air's reach of the camera
// the ellipsoid and that sphere part by metres.
glm::dvec3 atmosphereCamera(const Ellipsoid& shape, double radius_m, const glm::dvec3& camera_m);

// Writes frame.haze*: the media's coefficients and the light in the air for the sun along unit
// `sun` (planet-fixed) over the ground below `cameraFromCentre_m`: the sun's irradiance at the top,
// exposed, times its transmittance down to the bottom radius there (0 once the sun is below the
// horizon), and down to the mean height of the Rayleigh scattering between that ground and the
// camera (hazeSunAloft); and the radiance of the sky above (its irradiance there / pi, from `irradiance`, the
// atmosphere's sky irradiance table, AtmosphereLuts::irradianceData) and of the ground below (the
// sky's and the sun's light times the ground albedo / pi), averaged over the sphere; and the sky's
// light on flat ground there, which lights the ground with the sun's (hazeGroundLight in
// terrain_haze.glsl) as the atmosphere's tables do in `full`; and frame.skyZenith, skyHorizon: the
// haze's own sky straight up and at the horizon there, which the sea reflects (without air they
// keep the renderer's fixed colours).
// `atmosphere` nullptr (no atmosphere, or the atmosphere off): all zero, no haze.
void writeHazeConstants(gpu::TerrainFrame& frame, const gpu::AtmosphereGpu* atmosphere, const float* irradiance,
                        const glm::dvec3& cameraFromCentre_m, const glm::dvec3& sun);

// The sky irradiance at the atmosphere's bottom for the sun at cosine `muS` to the zenith, from the
// irradiance table (vec4 texels, atmosphere_layout.h), interpolated as the shaders do.
glm::dvec3 hazeSkyIrradiance(const float* irradiance, double muS);

// The transmittance of the atmosphere from radius `r_m` along a ray whose cosine to the zenith is
// `mu` to the top (0 where the ray meets the planet), by a fine midpoint sum in double.
glm::dvec3 hazeSunTransmittance(const gpu::AtmosphereGpu& atmosphere, double r_m, double mu);

}  // namespace globe
