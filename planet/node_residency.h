#pragma once
// What the selection needs from whoever owns node payloads (the future node/payload pool; tests use
// fakes): is a node drawable, please make one drawable, and — once a payload is known — the node's
// real radius range so its bounds can be tightened. Selection never allocates or generates anything.
#include <optional>

#include "planet/node_bounds.h"
#include "planet/node_id.h"

namespace globe {

enum class RequestPriority : int {
  kVisible = 0,  // children of a visible node that wants to refine: the parent is drawn meanwhile
  kRoot = 1,     // a visible root (level 0) that is not resident: nothing can be drawn there yet
};

class NodeResidency {
 public:
  virtual ~NodeResidency() = default;
  // The node's payload (mesh, normal map) is ready to draw.
  virtual bool isResident(const NodeId& node) const = 0;
  // Ask for a node's payload; distance_m from the camera to the node's bounds orders the queue.
  virtual void request(const NodeId& node, RequestPriority priority, double distance_m) = 0;
  // The node's real min/max surface radius (metres) once its payload is known; nullopt before, in
  // which case the configured elevation range is used. Values must contain the node's whole surface
  // at its children's resolution too (the pool pads them); only known ranges feed the LOD ranges'
  // diagonals.
  virtual std::optional<RadiusRange> knownRadiusRange(const NodeId& node) const {
    (void)node;
    return std::nullopt;
  }
};

}  // namespace globe
