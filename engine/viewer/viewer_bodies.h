#pragma once
// Bodies the viewer drops where you look (key B, docs/physics.md): a physics simulation on GPU
// collision meshes (engine/collision) stepped at its fixed step with the frame time, and the bodies
// as screen discs for the overlay. Terrain mode only; rebuilt with the planet on live reload.
#include "engine/collision/gpu_collision_mesh_source.h"
#include "engine/viewer/overlay.h"
#include "planet/camera/camera.h"
#include "planet/physics/physics_simulation.h"

#include <memory>
#include <vector>

namespace globe {

class ViewerBodies {
 public:
  // `device` and `model` must outlive it.
  ViewerBodies(vk::Device& device, const ElevationModel& model, double surfaceGravity_m_s2, uint32_t cells);

  // Drops a 1 m sphere (then a box, then a capsule, in turn) 3 m above where the view ray meets
  // the exact surface; false when it meets none within 100 km.
  bool dropWhereLooking(const Camera& camera);
  // Advances by `dt_s` of wall time in fixed steps (at most 8 a frame: a slow frame slows the bodies).
  void advance(double dt_s);
  // The bodies in front of the camera as discs on a width x height screen.
  std::vector<OverlayDisc> discs(const Camera& camera, double width_px, double height_px) const;
  size_t count() const { return simulation_->world().bodyCount(); }

 private:
  const ElevationModel& model_;
  GpuCollisionMeshSource source_;
  std::unique_ptr<PhysicsSimulation> simulation_;
  double pending_s_ = 0.0;
};

}  // namespace globe
