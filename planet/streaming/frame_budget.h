#pragma once
// Per-frame budgets (docs/streaming.md, "Frame budgets"): whatever the planet, a frame draws at most
// so many nodes and triangles and sends at most so many generation requests; memory is the pool's
// RAM and VRAM budgets. A planet whose relief makes the LOD ranges refine everywhere (amplitudes of
// 1e6 m, gain 1 with many octaves) is then drawn coarser instead of running away: the deepest level
// is capped where the LOD ranges alone show the budget would be overrun many times, lowered within
// the frame until the selection fits, and raised again one level a frame while the next level is
// predicted to fit. Capping the depth keeps the selection a restricted
// quadtree (it replaces every deeper node by its ancestor at the cap, so neighbours still differ by
// at most one level) and its morph bands unchanged. A warning says so once.
#include "planet/core/error.h"
#include "planet/lod/node_residency.h"
#include "planet/lod/selection.h"

#include <cstdint>
#include <string>
#include <vector>

namespace globe {

class PayloadPool;

struct FrameBudget {
  // Defaults: above every view of the shipped planets at every preset and every `globe trade`
  // configuration (largest: 6276 nodes, g16 x4; 13.7 M triangles, g64 x2 d24; docs/tradeoffs.md).
  uint32_t maxDrawnNodes = 8192;       // nodes drawn per frame, full and partial; >= 30 (the roots)
  uint64_t maxTriangles = 16'000'000;  // triangles submitted per frame (grids and skirts)
  uint32_t maxRequests = 8192;         // generation requests per frame (look-ahead: half of them)
};

// Errors name the field (max_drawn_nodes, max_triangles, max_requests).
Status validateFrameBudget(const FrameBudget& budget, uint64_t trianglesPerNode);

// The selection of one frame under a FrameBudget. Stands between the selector and the pool: the
// pool answers residency, and the requests of the selection that is finally kept (not of the
// passes thrown away for being over budget) go to the pool, at most maxRequests of them.
class BudgetedSelection final : public NodeResidency {
 public:
  // `trianglesPerNode`: the most triangles one drawn node submits (full grid and four skirts), so
  // maxTriangles becomes a node count. `maxDepth`: the configured deepest level.
  BudgetedSelection(const FrameBudget& budget, uint64_t trianglesPerNode, int maxDepth);

  // Selects `camera`'s view into `out` within the budget and forwards its requests to `pool`.
  Status select(LodSelector& selector, SelectionCamera camera, PayloadPool& pool, Selection& out);

  int depthCap() const { return depthCap_; }
  // The cap will rise next frame: the view is not final yet (Terrain::converged).
  bool rising() const { return rising_; }
  // Requests the budget turned away this frame.
  uint32_t droppedRequests() const { return dropped_; }
  // Set once, the first time the budget made a frame coarser.
  const std::string& warning() const { return warning_; }
  uint32_t nodeLimit() const { return nodeLimit_; }

  bool isResident(const NodeId& node) const override;
  bool isResidentForPrefetch(const NodeId& node) const override;
  void request(const NodeId& node, RequestPriority priority, double distance_m) override;
  std::optional<RadiusRange> knownRadiusRange(const NodeId& node) const override;
  std::optional<double> knownGeometricError(const NodeId& node) const override;

 private:
  struct Request {
    NodeId node;
    RequestPriority priority;
    double distance_m;
  };
  void warnLimited();
  // The deepest cap whose levels, by the LOD ranges alone, draw at most `nodes` nodes.
  int deepestCapWithin(const LodSelector& selector, double nodes) const;

  FrameBudget budget_;
  uint64_t trianglesPerNode_;
  int maxDepth_;
  uint32_t nodeLimit_;
  int depthCap_;
  bool rising_ = false;
  uint32_t dropped_ = 0;
  PayloadPool* pool_ = nullptr;  // during select()
  std::vector<Request> requests_;
  std::string warning_;
};

}  // namespace globe
