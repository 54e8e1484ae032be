#pragma once
// Turns a read-back frame into an image file's content: linear colour plus the per-pixel
// distance along the view ray in metres (+inf where nothing was drawn).
#include "engine/io/image_io.h"
#include "engine/render/offscreen_target.h"
#include "engine/vk/graphics_pipeline.h"
#include "planet/camera/camera.h"

namespace globe {

// The view-ray basis of the fullscreen passes (fullscreen.vert + a ray-casting fragment shader):
// right.w = tan(horizontal fov / 2), up.w = tan(vertical fov / 2), forward.w = `forwardW` (a
// per-shader extra: near plane, grid spacing, ...). Vulkan NDC: y grows downwards.
struct ViewRays {
  float right[4];
  float up[4];
  float forward[4];
};
ViewRays viewRays(const Camera& camera, float forwardW);
// A fullscreen pass: fullscreen.vert's one triangle and `fragmentShader`, push constants only.
vk::GraphicsPipelineDesc fullscreenPassDesc(const char* fragmentShader, uint32_t pushConstantBytes);

// Distance (metres) along the ray through pixel centre (x, y) for reversed-Z device depth `depth`.
double rayDistanceFromDepth(const Camera& camera, uint32_t width, uint32_t height, double x, double y, float depth);

ImageRgba toImage(const ReadbackImage& frame, const Camera& camera);

}  // namespace globe
