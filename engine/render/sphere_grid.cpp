#include "engine/render/sphere_grid.h"

#include "engine/render/render_output.h"

#include <cmath>

namespace globe {

namespace {
struct Push {  // layout of sphere_grid.frag's push constants
  double cameraAndRadius[4];
  ViewRays rays;  // forward.w: grid spacing (degrees)
};
static_assert(sizeof(Push) == 80);
}  // namespace

SphereGrid::SphereGrid(vk::Device& device)
    : pipeline_(device, [] {
        vk::GraphicsPipelineDesc d = fullscreenPassDesc("sphere_grid.frag", sizeof(Push));
        d.depthTest = false;
        d.depthWrite = false;
        d.blend = true;
        return d;
      }()) {}

void SphereGrid::record(VkCommandBuffer cmd, const Camera& camera, double radius_m, double spacing_deg) const {
  Push push{{camera.position_m.x, camera.position_m.y, camera.position_m.z, radius_m},
            viewRays(camera, float(spacing_deg))};
  pipeline_.bind(cmd, {}, &push, sizeof(push));
  vkCmdDraw(cmd, 3, 1, 0, 0);
}

}  // namespace globe
