#include "engine/render/render_output.h"

#include <cmath>
#include <limits>

namespace globe {

vk::GraphicsPipelineDesc fullscreenPassDesc(const char* fragmentShader, uint32_t pushConstantBytes) {
  vk::GraphicsPipelineDesc d;
  d.vertexShader = "fullscreen.vert";
  d.fragmentShader = fragmentShader;
  d.pushConstantBytes = pushConstantBytes;
  return d;
}

ViewRays viewRays(const Camera& camera, float forwardW) {
  double tanY = std::tan(camera.verticalFov_rad * 0.5);
  return {{float(camera.right.x), float(camera.right.y), float(camera.right.z), float(tanY * camera.aspect)},
          {float(camera.up.x), float(camera.up.y), float(camera.up.z), float(tanY)},
          {float(camera.forward.x), float(camera.forward.y), float(camera.forward.z), forwardW}};
}

double rayDistanceFromDepth(const Camera& camera, uint32_t width, uint32_t height, double x, double y, float depth) {
  if (!(depth > 0.0f)) return std::numeric_limits<double>::infinity();
  double tanY = std::tan(camera.verticalFov_rad * 0.5);
  double nx = (x + 0.5) / width * 2.0 - 1.0;
  double ny = (y + 0.5) / height * 2.0 - 1.0;
  // Ray direction in view space (forward = 1): its length converts axial distance to ray distance.
  double lengthPerAxial =
      std::sqrt(1.0 + (nx * tanY * camera.aspect) * (nx * tanY * camera.aspect) + (ny * tanY) * (ny * tanY));
  double axial = camera.near_m / double(depth);
  return axial * lengthPerAxial;
}

ImageRgba toImage(const ReadbackImage& frame, const Camera& camera) {
  ImageRgba image{frame.width, frame.height, frame.rgba, {}};
  image.z.resize(frame.depth.size());
  for (uint32_t y = 0; y < frame.height; ++y)
    for (uint32_t x = 0; x < frame.width; ++x)
      image.z[size_t(y) * frame.width + x] =
          float(rayDistanceFromDepth(camera, frame.width, frame.height, x, y, frame.depthAt(x, y)));
  return image;
}

}  // namespace globe
