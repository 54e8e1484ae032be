#pragma once
// Draws rigid bodies into a rendered frame: each body's surface points (PhysicsWorld::surfacePoints)
// projected through the frame's camera and splatted as small lit discs, depth-tested against the
// frame's per-pixel ray distances when it has them. A picture of where bodies rest, not a renderer.
#include "engine/io/image_io.h"
#include "planet/camera/camera.h"
#include "planet/physics/physics_world.h"

namespace globe {

// Colour per shape: spheres red, boxes yellow, capsules cyan. Returns how many bodies were visible.
uint32_t drawBodies(ImageRgba& image, const Camera& camera, const PhysicsWorld& world);

}  // namespace globe
