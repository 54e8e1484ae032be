#pragma once
// Where the terrain's shadow maps lie (cascaded shadow maps [Dimitrov 2007; Engel 2006]): each
// cascade is an orthographic view along the sunlight over a patch of ground around the camera, the
// patches growing by kShadowCascadeRatio from a few times the camera's height above the ground. A
// fragment takes the finest cascade whose box holds it (terrain_fragment.glsl). The box holds the
// receivers (the ground patch, with a relief band), and a caster between a receiver and the sun
// lies on the same light ray, so inside the box too; casters nearer the sun than the box's near
// plane are clamped onto it (depthClamp). Pure math: tested without a device.
#include "planet/camera/camera.h"
#include "shaders/include/terrain_layout.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>

namespace globe {

inline constexpr uint32_t kShadowCascades = GLOBE_SHADOW_CASCADES;
// Each cascade's ground radius over the previous one's.
inline constexpr double kShadowCascadeRatio = 5.0;

struct ShadowCascade {
  // Camera-relative metres (planet-fixed axes, as the terrain's vertices) to the cascade's clip
  // space: x, y in [-1, 1] across the sunlight, z in [0, 1] along it (0 nearest the sun).
  glm::dmat4 clipFromCamera{1.0};
  double radius_m = 0.0;  // ground radius the cascade covers around its centre
  double texel_m = 0.0;   // the widest of its texels across the sunlight (metres)
  double depth_m = 0.0;   // metres along the sunlight that depth 0..1 spans
};

struct ShadowCascades {
  std::array<ShadowCascade, kShadowCascades> cascades{};
  uint32_t count = 0;  // 0: no shadows (the camera too high for relief to cast visible ones, or the sun set)
};

struct ShadowView {
  const Camera* camera = nullptr;
  glm::dvec3 sun{0.0, 0.0, 1.0};   // unit, towards the sun, planet-fixed
  double groundRadius_m = 0.0;     // the ground's radius under the camera (metres from the centre)
  glm::dvec2 terrainRadii_m{0.0};  // the lowest and the highest terrain's radii on the planet
  uint32_t resolution = 2048;      // texels per side of each cascade's map
};

// The cascades for a view: none above kShadowMaxHeight_m over the ground or with the sun 5 degrees
// or more below the camera's horizon; a cascade is left out when it would cover more than a quarter
// of the planet's radius (a flat box no longer fits the curved ground).
ShadowCascades fitShadowCascades(const ShadowView& view);

// The last cascade's shadows fade out from this fraction of its box's half-width to its rim.
inline constexpr float kShadowFadeStart = 0.8f;

// A fragment's depth bias in its cascade's texels (widened by the slope, terrain_shadows.glsl).
inline constexpr double kShadowBiasTexels = 2.0;

// Whether the sun in direction `sun` stands high enough over the horizon of `up` (unit vectors) for
// relief to cast shadows: no more than 5 degrees below it.
bool sunAboveShadowLimit(const glm::dvec3& up, const glm::dvec3& sun);

// How far from the point under the camera the cascades fitShadowCascades draws reach (metres): the
// last one's centre offset plus its radius; 0 when none is drawn (too high, or `sunUp` false).
double shadowReach_m(double heightAboveGround_m, double groundRadius_m, bool sunUp);

// Above this height over the ground the relief's shadows are sub-pixel (10 km of relief from 1000 km
// at 1280x720 and 60 degrees) and no cascade is drawn.
inline constexpr double kShadowMaxHeight_m = 1.0e6;

}  // namespace globe
