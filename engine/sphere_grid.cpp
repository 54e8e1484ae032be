#include "engine/sphere_grid.h"

#include <cmath>

namespace globe {

namespace {
struct Push {  // layout of sphere_grid.frag's push constants
  double cameraAndRadius[4];
  float right[4];
  float up[4];
  float forward[4];
};
static_assert(sizeof(Push) == 80);
}  // namespace

SphereGrid::SphereGrid(vk::Device& device)
    : pipeline_(device, [] {
        vk::GraphicsPipelineDesc d;
        d.vertexShader = "fullscreen.vert";
        d.fragmentShader = "sphere_grid.frag";
        d.pushConstantBytes = sizeof(Push);
        d.depthTest = false;
        d.depthWrite = false;
        d.blend = true;
        return d;
      }()) {}

void SphereGrid::record(VkCommandBuffer cmd, const Camera& camera, double radius_m, double spacing_deg) const {
  double tanY = std::tan(camera.verticalFov_rad * 0.5);
  Push push{{camera.position_m.x, camera.position_m.y, camera.position_m.z, radius_m},
            {float(camera.right.x), float(camera.right.y), float(camera.right.z), float(tanY * camera.aspect)},
            {float(camera.up.x), float(camera.up.y), float(camera.up.z), float(tanY)},
            {float(camera.forward.x), float(camera.forward.y), float(camera.forward.z), float(spacing_deg)}};
  pipeline_.bind(cmd, {}, &push, sizeof(push));
  vkCmdDraw(cmd, 3, 1, 0, 0);
}

}  // namespace globe
