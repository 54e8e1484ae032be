#pragma once
// What the selection needs from whoever owns node payloads (the node/payload pool; tests use fakes):
// is a node drawable, please make one drawable, and — once a payload is known — the node's real
// radius range so its bounds can be tightened. Selection never allocates or generates anything.
//
// Two kinds of question: isResident() is asked for nodes the current view draws or waits for (the
// pool keeps those); isResidentForPrefetch() is asked by the look-ahead (nodes the view may need
// soon) and must not count as "wanted", so prefetching never pins nodes against eviction.
#include <optional>

#include "planet/geometry/node_bounds.h"
#include "planet/geometry/node_id.h"

namespace globe {

// Queue order: lower first; within a priority, nearer first. Whatever the current view waits for
// comes before any look-ahead, so prefetching can only use budget the view leaves over.
// The collision meshes (planet/physics/collision_mesh_pool.h) share the order: a predicted contact
// comes before everything, the objects' radius of interest after what the view waits for.
enum class RequestPriority : int {
  kContact = -1,   // collision: a body touches the node within the look-ahead; generated synchronously
  kVisible = 0,    // children of a visible node that wants to refine: the parent is drawn meanwhile
  kRoot = 1,       // a visible root (level 0) that is not resident: nothing can be drawn there yet.
                   // Only happens before anything under it is resident, so it never competes with
                   // kVisible in practice; it sorts after it only nominally.
  kCollision = 2,  // collision: the node is within an object's radius of interest; asynchronous
  kPrefetch = 3,   // look-ahead: the next level below a node the camera approaches, and the ring of
                   // frustum-culled nodes around the view (docs/streaming.md)
};

class NodeResidency {
 public:
  virtual ~NodeResidency() = default;
  // The node's payload (mesh, normal map) is ready to draw.
  virtual bool isResident(const NodeId& node) const = 0;
  // Like isResident(), for the look-ahead: does NOT mark the node as wanted by the current frame.
  virtual bool isResidentForPrefetch(const NodeId& node) const { return isResident(node); }
  // Ask for a node's payload; distance_m from the camera to the node's bounds orders the queue.
  // kPrefetch requests never make the owner drop anything the current view draws or waits for.
  virtual void request(const NodeId& node, RequestPriority priority, double distance_m) = 0;
  // The node's real min/max surface radius (metres) once its payload is known; nullopt before, in
  // which case the configured elevation range is used. Values must contain the node's whole surface
  // at its children's resolution too (the pool pads them); only known ranges feed the LOD ranges'
  // diagonals.
  virtual std::optional<RadiusRange> knownRadiusRange(const NodeId& node) const {
    (void)node;
    return std::nullopt;
  }
  // The node's geometric error (metres) once its payload is known: the largest distance a vertex of
  // its mesh moves when it morphs to its parent's mesh. Feeds tolerance-driven ranges (LodRanges).
  virtual std::optional<double> knownGeometricError(const NodeId& node) const {
    (void)node;
    return std::nullopt;
  }
};

}  // namespace globe
