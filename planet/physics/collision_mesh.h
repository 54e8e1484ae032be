#pragma once
// A collision mesh: the vertex grid of one node's payload (shaders/include/payload_layout.h) without
// its sample ring or normals, as the renderer draws it unmorphed — (cells + 1)^2 vertices relative
// to the payload's node centre, each cell split along its (i, j)-(i+1, j+1) diagonal. The positions
// are the payload's quantised floats widened to double, so centre + vertex is the same double from
// both nodes of a seam (planet/streaming/payload_reference.h) and neighbouring meshes close exactly.
//
// CollisionMeshSource fills them: asynchronously (generate, then collect on a later step) or
// synchronously for a predicted contact (generateNow). The GPU source (engine/collision) reads back
// the payload kernel's positions; CpuCollisionMeshSource uses the kernel's CPU reference, which is
// bit-identical in positions (tests/engine/payload_generator_test.cpp).
#include "planet/geometry/node_bounds.h"
#include "planet/geometry/node_id.h"
#include "planet/model/elevation_model.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

namespace globe {

struct CollisionMesh {
  NodeId node;
  uint32_t cells = 0;
  glm::dvec3 centre_m{0.0};        // the payload's snapped node centre, planet-centred
  std::vector<double> vertices_m;  // xyz per vertex, relative to centre_m, row j = v index
  RadiusRange radius;              // of the vertices, metres from the planet centre

  size_t vertexCount() const { return vertices_m.size() / 3; }
  glm::dvec3 vertex(uint32_t i, uint32_t j) const {
    const size_t k = 3 * (size_t(j) * (cells + 1) + i);
    return {vertices_m[k], vertices_m[k + 1], vertices_m[k + 2]};
  }
  // Bytes of the vertices plus Bullet's per-node structures (see collisionMeshBytes).
  size_t bytes() const;
};

// Memory one resident mesh of `cells` costs: vertices (double, twice: the pool's and the physics
// world's copy in the node's tangent frame), the grid shape's block heights and a fixed overhead
// (the shape and one collision object per world).
size_t collisionMeshBytes(uint32_t cells);

// Triangle indices of the (cells + 1)^2 vertex grid, counter-clockwise seen from outside, in the
// renderer's split: (i,j) (i+1,j) (i+1,j+1) and (i,j) (i+1,j+1) (i,j+1).
std::vector<int> collisionGridIndices(uint32_t cells);

// The mesh from a payload slot's position block (GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells)^2 vec4s).
CollisionMesh collisionMeshFromPayload(const NodeId& node, const glm::dvec3& centre_m, uint32_t cells,
                                       std::span<const glm::vec4> positions);

class CollisionMeshSource {
 public:
  virtual ~CollisionMeshSource() = default;
  virtual uint32_t cells() const = 0;
  // Starts generating `nodes`; results come back through collect(). Must not block.
  virtual void generate(std::span<const NodeId> nodes) = 0;
  // Appends the meshes finished since the last call. Must not block.
  virtual void collect(std::vector<CollisionMesh>& finished) = 0;
  // Generates one mesh and waits for it (a predicted contact).
  virtual CollisionMesh generateNow(const NodeId& node) = 0;
  // Generations started and not yet collected.
  virtual uint32_t inFlight() const = 0;
  // Blocks until every generation started so far is collectable (a loading phase, not a step).
  virtual void finishAll() = 0;
};

// The payload kernel's CPU reference (fillPayloadReference). "Asynchronous" jobs are computed in
// generate() and handed out by the next collect(), so CPU tests see the GPU source's timing.
class CpuCollisionMeshSource final : public CollisionMeshSource {
 public:
  // `model` must outlive the source.
  CpuCollisionMeshSource(const ElevationModel& model, uint32_t cells);
  uint32_t cells() const override { return cells_; }
  void generate(std::span<const NodeId> nodes) override;
  void collect(std::vector<CollisionMesh>& finished) override;
  CollisionMesh generateNow(const NodeId& node) override;
  uint32_t inFlight() const override { return uint32_t(ready_.size()); }
  void finishAll() override {}

 private:
  const ElevationModel& model_;
  uint32_t cells_;
  std::vector<glm::vec4> slot_;
  std::vector<CollisionMesh> ready_;
};

}  // namespace globe
