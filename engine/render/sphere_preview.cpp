#include "engine/render/sphere_preview.h"

#include "engine/render/render_output.h"

#include <cmath>

namespace globe {

namespace {
struct Push {
  double cameraAndRadius[4];
  ViewRays rays;  // forward.w: near plane (m)
  float sun[4];
};
static_assert(sizeof(Push) == 96);
}  // namespace

SpherePreview::SpherePreview(vk::Device& device)
    : pipeline_(device, fullscreenPassDesc("sphere_preview.frag", sizeof(Push))) {}

void SpherePreview::record(VkCommandBuffer cmd, const Camera& camera, double radius_m,
                           const glm::dvec3& sunDirection) const {
  glm::dvec3 sun = glm::normalize(sunDirection);
  Push push{{camera.position_m.x, camera.position_m.y, camera.position_m.z, radius_m},
            viewRays(camera, float(camera.near_m)),
            {float(sun.x), float(sun.y), float(sun.z), 0.0f}};
  pipeline_.bind(cmd, {}, &push, sizeof(push));
  vkCmdDraw(cmd, 3, 1, 0, 0);
}

}  // namespace globe
