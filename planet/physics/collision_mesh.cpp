#include "planet/physics/collision_mesh.h"

#include "planet/streaming/payload_reference.h"
#include "shaders/include/payload_layout.h"

#include <cmath>
#include <limits>

namespace globe {

size_t collisionMeshBytes(uint32_t cells) {
  const size_t vertices = size_t(cells + 1) * size_t(cells + 1);
  const size_t blocks = size_t((cells + 3) / 4) * size_t((cells + 3) / 4);
  // The pool's vertices, the physics world's copy in the node's tangent frame, the grid shape's
  // block heights (planet/physics/grid_mesh_shape.h; no BVH), objects and bookkeeping.
  return 2 * vertices * 3 * sizeof(double) + blocks * 2 * sizeof(double) + 2048;
}

size_t CollisionMesh::bytes() const { return collisionMeshBytes(cells); }

std::vector<int> collisionGridIndices(uint32_t cells) {
  std::vector<int> indices;
  indices.reserve(6 * size_t(cells) * size_t(cells));
  const int side = int(cells) + 1;
  for (int j = 0; j < int(cells); ++j) {
    for (int i = 0; i < int(cells); ++i) {
      const int v00 = j * side + i, v10 = v00 + 1, v01 = v00 + side, v11 = v01 + 1;
      indices.insert(indices.end(), {v00, v10, v11, v00, v11, v01});
    }
  }
  return indices;
}

CollisionMesh collisionMeshFromPayload(const NodeId& node, const glm::dvec3& centre_m, uint32_t cells,
                                       std::span<const glm::vec4> positions) {
  CollisionMesh mesh;
  mesh.node = node;
  mesh.cells = cells;
  mesh.centre_m = centre_m;
  const uint32_t samples = GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells);
  mesh.vertices_m.reserve(3 * size_t(cells + 1) * size_t(cells + 1));
  mesh.radius = {std::numeric_limits<double>::infinity(), 0.0};
  for (uint32_t j = 0; j <= cells; ++j) {
    for (uint32_t i = 0; i <= cells; ++i) {
      const glm::vec4& p = positions[size_t(j + 1) * samples + (i + 1)];
      const glm::dvec3 rel{double(p.x), double(p.y), double(p.z)};
      mesh.vertices_m.insert(mesh.vertices_m.end(), {rel.x, rel.y, rel.z});
      const glm::dvec3 world = centre_m + rel;
      const double r = std::sqrt((world.x * world.x + world.y * world.y) + world.z * world.z);
      mesh.radius.min_m = std::min(mesh.radius.min_m, r);
      mesh.radius.max_m = std::max(mesh.radius.max_m, r);
    }
  }
  return mesh;
}

CpuCollisionMeshSource::CpuCollisionMeshSource(const ElevationModel& model, uint32_t cells)
    : model_(model), cells_(cells), slot_(GLOBE_PAYLOAD_VEC4_PER_SLOT(cells)) {}

void CpuCollisionMeshSource::generate(std::span<const NodeId> nodes) {
  for (const NodeId& node : nodes) ready_.push_back(generateNow(node));
}

void CpuCollisionMeshSource::collect(std::vector<CollisionMesh>& finished) {
  for (CollisionMesh& mesh : ready_) finished.push_back(std::move(mesh));
  ready_.clear();
}

CollisionMesh CpuCollisionMeshSource::generateNow(const NodeId& node) {
  const gpu::PayloadJob job = makePayloadJob(node, 0, model_);
  fillPayloadReference(model_, job, cells_, slot_);
  const uint32_t samples = GLOBE_PAYLOAD_SAMPLES_PER_SIDE(cells_);
  return collisionMeshFromPayload(node, {job.centre.x, job.centre.y, job.centre.z}, cells_,
                                  std::span<const glm::vec4>(slot_).first(size_t(samples) * samples));
}

}  // namespace globe
