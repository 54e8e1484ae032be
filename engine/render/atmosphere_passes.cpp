#include "engine/render/atmosphere_passes.h"

#include "engine/render/render_output.h"
#include "engine/render/terrain_haze.h"

#include <glm/geometric.hpp>

namespace globe {
namespace {

struct SkyPush {
  ViewRays rays;
  float camera[4];  // xyz: camera minus planet centre, w: radius of the lowest terrain, metres
  float sun[4];     // unit, towards the sun
};
static_assert(sizeof(SkyPush) == 80);

}  // namespace

void AerialPerspectivePass::prepare(VkCommandBuffer cmd, const PassFrame& frame, PassMarks&) {
  Camera air = frame.camera;
  air.position_m = atmosphereCamera(style_.shape, style_.radius_m, frame.camera.position_m);
  view_.record(cmd, air, style_.sunDirection, style_.airTerrainRadii_m, frame.frameIndex);
}

SkyPass::SkyPass(vk::Device& device, const TerrainStyle& style, TargetFormat target, uint32_t gridCells,
                 GridRanges grid)
    : style_(style),
      cells_(gridCells),
      grid_(grid),
      sky_(device, skyDesc(target, sizeof(SkyPush), false)),
      skyFromSpace_(device, skyDesc(target, sizeof(SkyPush), true)) {}

void SkyPass::record(VkCommandBuffer cmd, const PassFrame& frame, PassMarks& marks, DrawStats& stats) {
  marks.write(cmd, kMarkSkyBegin);
  if (style_.sky && style_.atmosphere) {
    const Camera& camera = frame.camera;
    // Camera minus planet centre in double, then float: the sky never sees the planet-scale sum.
    const glm::dvec3 air = atmosphereCamera(style_.shape, style_.radius_m, camera.position_m);
    const glm::vec3 c(air);
    const glm::vec3 sun(glm::normalize(style_.sunDirection));
    // The sky's screen grid is the terrain's full grid (its index range 0), one vertex per sample.
    SkyPush push{viewRays(camera, float(cells_)),
                 {c.x, c.y, c.z, float(style_.airTerrainRadii_m.x)},
                 {sun.x, sun.y, sun.z, 0.0f}};
    const AtmosphereLuts& a = *style_.atmosphere;
    const double top_m = double(a.packed().radii.y);
    const bool fromSpace = glm::length(air) > top_m;
    (fromSpace ? skyFromSpace_ : sky_)
        .bind(cmd, {a.parameters(), a.transmittance(), a.irradiance(), a.scattering()}, &push, sizeof(push));
    vkCmdBindIndexBuffer(cmd, grid_.indices, 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, grid_.count[0], 1, grid_.first[0], 0, 0);
    // From space, the sun in open space: a square round its disc (terrain_sky.vert, instance 1).
    if (fromSpace) vkCmdDraw(cmd, 6, 1, 0, 1);
    ++stats.drawCalls;
  }
  marks.write(cmd, kMarkSkyEnd);
}

}  // namespace globe
