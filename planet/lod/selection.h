#pragma once
// CDLOD node selection over the 30 face quadtrees [Strugar 2009; Frasson 2018, §3.3.1, Listing 3.1].
// Depth-first from the roots: a node culled by the frustum or the horizon is dropped with its subtree;
// a node at max depth, or whose bounds miss the ball of radius R(depth) around the camera, is selected;
// otherwise its four children are visited — those that miss that same ball are selected as *partial*
// nodes (drawn at half resolution, i.e. their parent's LOD). If any child is not resident, the node
// itself is drawn (never a hole) and the missing children are requested.
//
// No allocation per frame: results go to a caller-owned Selection whose vector keeps its capacity;
// node bounds are built on the fly from the parent's (children share its side planes and corners).
//
// Prefetch (docs/streaming.md): besides what it draws, the selection asks for what the view will
// probably need soon, with RequestPriority::kPrefetch and through isResidentForPrefetch() (which does
// not pin nodes): (a) the next level below a drawn node once the camera is within
// nextLevelRangeFactor × its refine range, so descending does not wait for generation; (b) a ring of
// frustum-culled (not horizon-culled) nodes, refined as if visible out to ringRangeFactor × the
// refine ranges, so turning the head finds them ready. Prefetch never changes the selection itself.
//
// Camera inside the planet (or below the minimum elevation): horizon culling is off for that frame,
// frustum culling and range tests work as usual (nodes nearest the camera are refined). A non-finite
// camera position is an Error and leaves `out` empty.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "planet/core/error.h"
#include "planet/geometry/face_mapping.h"
#include "planet/geometry/node_bounds.h"
#include "planet/lod/frustum.h"
#include "planet/lod/horizon_cone.h"
#include "planet/lod/lod_ranges.h"
#include "planet/lod/node_residency.h"

namespace globe {

struct PrefetchConfig {
  bool enabled = true;
  // (a) next level: children of a drawn node are prefetched when the camera is within this factor of
  // the node's refine range (>= 1; 1 = off). Each 0.1 adds roughly a quarter of a level's nodes.
  double nextLevelRangeFactor = 1.25;
  // (b) ring: frustum-culled nodes are refined (prefetch only) as if visible, with refine ranges
  // scaled by this factor ([0, 1]; 0 = no ring, 1 = the whole 360° view at full detail; 0.5 = one
  // level coarser than the view would need, a quarter of the nodes).
  double ringRangeFactor = 0.5;
};

struct LodConfig {
  double radius_m = 6371000.0;       // planet radius (metres); the equatorial radius a of an ellipsoid
  double flattening = 0.0;           // (a - b) / a in [0, 0.5); 0 = a sphere (Ellipsoid)
  double minElevation_m = -11000.0;  // default node bounds until a payload's real range is known;
  double maxElevation_m = 9000.0;    // minElevation also sets the horizon occluder (R + min)
  LodRangeConfig ranges;
  bool horizonCulling = true;
  PrefetchConfig prefetch;
};

struct SelectedNode {
  NodeId id;             // level = id.level
  NodeMorph morph;       // metres; for a partial node, the band of its parent's depth over its square
  bool partial = false;  // draw at half resolution (the parent's LOD, sampling this node's quadrant)
  uint8_t quadrant = 0;  // id.quadrant(): where the node lies in its parent (0 for roots)
};

struct SelectionStats {
  uint32_t visited = 0;   // nodes whose bounds were tested (incl. partial children)
  uint32_t selected = 0;  // nodes written (full + partial)
  uint32_t partial = 0;
  uint32_t frustumCulled = 0;
  uint32_t horizonCulled = 0;
  uint32_t fallbacks = 0;         // nodes drawn in place of children that are not resident
  uint32_t requests = 0;          // kVisible and kRoot requests
  uint32_t prefetchRequests = 0;  // kPrefetch requests
  uint32_t prefetchVisited = 0;   // frustum-culled nodes walked by the ring prefetch
  uint32_t passes = 0;            // > 1 when an observed diagonal grew the ranges mid-selection
  // Budgets (SelectionCamera::maxDepth, maxNodes): nodes at the depth cap that the ranges would
  // refine, and whether the selection stopped at maxNodes (then `nodes` is incomplete: select again
  // with a lower cap).
  uint32_t heldBack = 0;
  bool overBudget = false;
};

struct Selection {
  std::vector<SelectedNode> nodes;  // caller-owned; cleared (capacity kept) by each select()
  SelectionStats stats;
};

struct SelectionCamera {
  glm::dvec3 position_m{0.0};        // planet-fixed metres
  const Frustum* frustum = nullptr;  // nullptr: no frustum culling
  // A frame budget's limits (planet/streaming/frame_budget.h): no node deeper than maxDepth is
  // selected or requested (-1: the configured max depth; a cap keeps the quadtree restricted, see
  // LodRanges), and the selection stops once it would select more than maxNodes (0: no limit).
  int maxDepth = -1;
  uint32_t maxNodes = 0;
};

class LodSelector {
 public:
  // Bad config values are an Error. `mapping` must outlive the selector.
  static Result<LodSelector> create(const LodConfig& config, const FaceMapping& mapping = RhombusFaceMapping::get());

  // Fills `out`. Requests for missing nodes go to `residency`.
  Status select(const SelectionCamera& camera, NodeResidency& residency, Selection& out);

  const LodConfig& config() const { return config_; }
  const LodRanges& ranges() const { return ranges_; }
  LodRanges& ranges() { return ranges_; }
  RadiusRange defaultRadiusRange() const { return defaultRange_; }
  const Ellipsoid& shape() const { return shape_; }
  // Bounds the selection uses for `node` (its known range, else the default).
  NodeBounds boundsFor(const NodeId& node, const NodeResidency& residency) const;

 private:
  LodSelector(const LodConfig& config, const FaceMapping& mapping, LodRanges ranges, const Ellipsoid& shape);
  struct Context;
  // What is known about a node when it is visited; the two visibility facts are inherited from the
  // parent, so a subtree wholly inside stops testing.
  struct VisitState {
    bool knownRange = false;     // its radius range was measured (not the planet-wide default)
    bool partial = false;        // outside its parent's refine range: drawn as a partial node
    bool insideFrustum = false;  // wholly inside the frustum (or there is no frustum)
    bool fullyVisible = false;   // wholly above the horizon
  };
  void visit(const NodeId& id, const NodeBounds& bounds, VisitState state, Context& ctx);
  // Frustum and horizon tests; false when the node is culled. Narrows `state` for the children.
  bool survivesCulling(const NodeId& id, const NodeBounds& bounds, VisitState& state, Context& ctx);
  void addSelected(const NodeId& id, bool partial, Context& ctx);
  // Requests the children that are not resident; true when all four are resident.
  bool requestMissingChildren(const std::array<NodeId, 4>& children, const NodeBounds& bounds, Context& ctx);
  void visitChildren(const NodeId& id, const NodeBounds& bounds, const std::array<NodeId, 4>& children, double range_m,
                     VisitState state, Context& ctx);
  // Walks a frustum-culled node for the ring prefetch: requests, never selects.
  void prefetchVisit(const NodeId& id, const NodeBounds& bounds, bool fullyVisible, Context& ctx);
  // Requests the children of `id` that are not resident, as prefetch; true when all are resident.
  bool prefetchChildren(const NodeId& id, double distance_m, Context& ctx);
  void selectOnce(Context& ctx);

  LodConfig config_;
  const FaceMapping* mapping_;
  LodRanges ranges_;
  Ellipsoid shape_;
  RadiusRange defaultRange_;
  std::array<NodeBounds, 30> rootBounds_;  // the 30 roots at the default range (corners, side planes)
};

}  // namespace globe
