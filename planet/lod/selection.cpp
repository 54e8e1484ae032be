#include "planet/lod/selection.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "planet/geometry/triacontahedron.h"

namespace globe {
namespace {

constexpr uint32_t kMaxPasses = 4;  // range growth converges fast; a cap keeps the frame bounded

bool isFinite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

struct LodSelector::Context {
  glm::dvec3 camera;
  const Frustum* frustum;
  HorizonCone horizon;
  NodeResidency* residency;
  Selection* out;
  bool grew;
  int maxDepth;       // the configured max depth or the caller's lower cap
  uint32_t maxNodes;  // 0: no limit
};

Result<LodSelector> LodSelector::create(const LodConfig& c, const FaceMapping& mapping) {
  const auto bad = [](const char* field, const char* message) { return Error::inField(field, message); };
  if (!(std::isfinite(c.radius_m) && c.radius_m > 0.0)) return bad("radius", "must be finite and > 0");
  if (!(std::isfinite(c.minElevation_m) && std::isfinite(c.maxElevation_m))) {
    return bad("elevation", "min and max elevation must be finite");
  }
  if (c.minElevation_m > c.maxElevation_m) return bad("elevation", "min elevation is above max elevation");
  if (c.radius_m + c.minElevation_m < 0.0) return bad("minElevation", "reaches below the planet centre");
  if (!(std::isfinite(c.prefetch.nextLevelRangeFactor) && c.prefetch.nextLevelRangeFactor >= 1.0)) {
    return bad("prefetch.nextLevelRangeFactor", "must be finite and >= 1");
  }
  if (!(c.prefetch.ringRangeFactor >= 0.0 && c.prefetch.ringRangeFactor <= 1.0)) {
    return bad("prefetch.ringRangeFactor", "must be in [0, 1]");
  }
  Result<Ellipsoid> shape = Ellipsoid::create(c.radius_m, c.flattening, "shape");
  if (!shape) return shape.error();
  // The ellipsoidal bounds need every surface point farther from the centre than p(n) is from the
  // normal line through it (NodeBounds::tighten); only an extreme shape with deep terrain fails this.
  double axisMin = 0.0, axisMax = 0.0;
  shape->axisOffsetRange_m(0.0, 1.0, axisMin, axisMax);
  if (!shape->isSphere() && !(shape->polarRadius_m() + c.minElevation_m > axisMax * (1.0 + 1e-9))) {
    return bad("minElevation", "reaches too deep for the ellipsoid (below its largest normal offset)");
  }
  Result<LodRanges> ranges = LodRanges::create(c.ranges, c.radius_m);
  if (!ranges) return ranges.error();
  return LodSelector(c, mapping, std::move(ranges.value()), *shape);
}

namespace {

// Distances from the centre (|p|) of every terrain point with ellipsoidal height in [min, max]:
// |p| >= dot(p, n) = N + h >= b + min, and |p| <= a + max(max, 0).
RadiusRange planetRadiusRange(const Ellipsoid& shape, double minElevation_m, double maxElevation_m) {
  const double a = shape.equatorialRadius_m();
  if (shape.isSphere()) return {a + minElevation_m, a + maxElevation_m};
  return {shape.polarRadius_m() + minElevation_m, a + std::max(0.0, maxElevation_m)};
}

}  // namespace

LodSelector::LodSelector(const LodConfig& config, const FaceMapping& mapping, LodRanges ranges, const Ellipsoid& shape)
    : config_(config),
      mapping_(&mapping),
      ranges_(std::move(ranges)),
      shape_(shape),
      defaultRange_(planetRadiusRange(shape, config.minElevation_m, config.maxElevation_m)) {
  for (int f = 0; f < kFaceCount; ++f) {
    rootBounds_[static_cast<size_t>(f)] =
        NodeBounds::forNode(mapping, {static_cast<uint8_t>(f), 0, 0, 0}, defaultRange_, shape_);
  }
}

NodeBounds LodSelector::boundsFor(const NodeId& node, const NodeResidency& residency) const {
  return NodeBounds::forNode(*mapping_, node, residency.knownRadiusRange(node).value_or(defaultRange_), shape_);
}

Status LodSelector::select(const SelectionCamera& camera, NodeResidency& residency, Selection& out) {
  out.nodes.clear();
  out.stats = {};
  if (!isFinite(camera.position_m)) return Error::inField("camera", "position is not finite");
  Context ctx{camera.position_m,
              camera.frustum,
              config_.horizonCulling ? HorizonCone(camera.position_m, shape_, config_.minElevation_m)
                                     : HorizonCone(camera.position_m, 0.0),
              &residency,
              &out,
              false,
              camera.maxDepth < 0 ? ranges_.maxDepth() : std::min(camera.maxDepth, ranges_.maxDepth()),
              camera.maxNodes};
  // A range that grows mid-pass may have let an earlier decision break the restriction: redo.
  do {
    ctx.grew = false;
    out.nodes.clear();
    const uint32_t passes = out.stats.passes + 1;
    out.stats = {};
    out.stats.passes = passes;
    ranges_.refresh();
    selectOnce(ctx);
  } while (ctx.grew && out.stats.passes < kMaxPasses);
  // Morph bands also depend on the diagonals observed during the pass (crack-freedom, see
  // LodRanges); they never change which nodes are selected, so they are written from the final ranges.
  ranges_.refresh();
  for (SelectedNode& n : out.nodes) n.morph = ranges_.morphFor(n.id, n.partial);
  return Ok{};
}

void LodSelector::selectOnce(Context& ctx) {
  for (int f = 0; f < kFaceCount; ++f) {
    const NodeId root{static_cast<uint8_t>(f), 0, 0, 0};
    const std::optional<RadiusRange> known = ctx.residency->knownRadiusRange(root);
    NodeBounds b = rootBounds_[static_cast<size_t>(f)];
    if (known) b.tighten(*known, shape_);
    visit(root, b, {known.has_value(), false, ctx.frustum == nullptr, false}, ctx);
  }
}

bool LodSelector::survivesCulling(const NodeId& id, const NodeBounds& b, VisitState& state, Context& ctx) {
  SelectionStats& stats = ctx.out->stats;
  if (!state.insideFrustum) {
    const Containment c = ctx.frustum->classify(b);
    if (c == Containment::kOutside) {
      ++stats.frustumCulled;
      if (config_.prefetch.enabled && config_.prefetch.ringRangeFactor > 0.0)
        prefetchVisit(id, b, state.fullyVisible, ctx);
      return false;
    }
    state.insideFrustum = c == Containment::kInside;
  }
  if (!state.fullyVisible) {
    const HorizonVisibility h = ctx.horizon.classify(b);
    if (h == HorizonVisibility::kHidden) {
      ++stats.horizonCulled;
      return false;
    }
    state.fullyVisible = h == HorizonVisibility::kFullyVisible;
  }
  return true;
}

void LodSelector::addSelected(const NodeId& id, bool partial, Context& ctx) {
  if (ctx.maxNodes > 0 && ctx.out->nodes.size() >= ctx.maxNodes) {
    ctx.out->stats.overBudget = true;  // visit() stops everywhere from here on
    return;
  }
  const int depth = id.level;
  ctx.out->nodes.push_back({id, {}, partial, static_cast<uint8_t>(depth > 0 ? id.quadrant() : 0)});
  ++ctx.out->stats.selected;
  if (partial) ++ctx.out->stats.partial;
}

bool LodSelector::requestMissingChildren(const std::array<NodeId, 4>& children, const NodeBounds& b, Context& ctx) {
  bool allResident = true;
  for (const NodeId& child : children) allResident = ctx.residency->isResident(child) && allResident;
  if (allResident) return true;
  const double distance = distanceToBounds(b, ctx.camera);
  for (const NodeId& child : children) {
    if (ctx.residency->isResident(child)) continue;
    ctx.residency->request(child, RequestPriority::kVisible, distance);
    ++ctx.out->stats.requests;
  }
  return false;
}

void LodSelector::visitChildren(const NodeId& id, const NodeBounds& b, const std::array<NodeId, 4>& children,
                                double range_m, VisitState state, Context& ctx) {
  std::array<std::optional<RadiusRange>, 4> known;
  std::array<RadiusRange, 4> childRadius;
  for (size_t q = 0; q < 4; ++q) {
    known[q] = ctx.residency->knownRadiusRange(children[q]);
    childRadius[q] = known[q].value_or(defaultRange_);
  }
  const std::array<NodeBounds, 4> bounds = childBounds(*mapping_, id, b, childRadius, shape_);
  for (size_t q = 0; q < 4; ++q) {
    const bool inRange = intersectsSphere(bounds[q], ctx.camera, range_m);
    visit(children[q], bounds[q], {known[q].has_value(), !inRange, state.insideFrustum, state.fullyVisible}, ctx);
  }
}

void LodSelector::visit(const NodeId& id, const NodeBounds& b, VisitState state, Context& ctx) {
  SelectionStats& stats = ctx.out->stats;
  if (stats.overBudget) return;
  ++stats.visited;
  if (!survivesCulling(id, b, state, ctx)) return;
  const int depth = id.level;
  if (state.knownRange && ranges_.observeDiagonal(depth, b.diagonal())) ctx.grew = true;
  if (state.knownRange && ranges_.toleranceDriven()) {
    const std::optional<double> error = ctx.residency->knownGeometricError(id);
    if (error && ranges_.observeError(id, *error)) ctx.grew = true;
  }
  if (state.partial) {
    addSelected(id, true, ctx);
    return;
  }
  if (depth == 0 && !ctx.residency->isResident(id)) {
    ctx.residency->request(id, RequestPriority::kRoot, distanceToBounds(b, ctx.camera));
    ++stats.requests;
    return;
  }
  const double range = depth < ranges_.maxDepth() ? ranges_.refineRangeOver(id) : 0.0;
  const bool refine = depth < ranges_.maxDepth() && intersectsSphere(b, ctx.camera, range);
  if (refine && depth >= ctx.maxDepth) ++stats.heldBack;  // a budget's cap keeps it coarser
  if (!refine || depth >= ctx.maxDepth) {
    addSelected(id, false, ctx);
    // Look-ahead (a): the camera is about to come within this node's refine range.
    if (depth < ctx.maxDepth && config_.prefetch.enabled && config_.prefetch.nextLevelRangeFactor > 1.0 &&
        intersectsSphere(b, ctx.camera, range * config_.prefetch.nextLevelRangeFactor)) {
      prefetchChildren(id, distanceToBounds(b, ctx.camera), ctx);
    }
    return;
  }
  std::array<NodeId, 4> children;
  for (int q = 0; q < 4; ++q) children[static_cast<size_t>(q)] = id.child(q);
  if (!requestMissingChildren(children, b, ctx)) {
    ++stats.fallbacks;
    addSelected(id, false, ctx);
    return;
  }
  visitChildren(id, b, children, range, state, ctx);
}

bool LodSelector::prefetchChildren(const NodeId& id, double distance_m, Context& ctx) {
  bool allResident = true;
  for (int q = 0; q < 4; ++q) {
    const NodeId child = id.child(q);
    if (ctx.residency->isResidentForPrefetch(child)) continue;
    allResident = false;
    ctx.residency->request(child, RequestPriority::kPrefetch, distance_m);
    ++ctx.out->stats.prefetchRequests;
  }
  return allResident;
}

void LodSelector::prefetchVisit(const NodeId& id, const NodeBounds& b, bool fullyVisible, Context& ctx) {
  // The selection's refinement rule with scaled ranges, minus everything about drawing: no partial
  // nodes, no restriction bookkeeping (nothing here is drawn), no diagonals observed (the ranges
  // stay a function of what is drawn). The horizon test stays: turning does not reveal what it hides.
  SelectionStats& stats = ctx.out->stats;
  if (stats.overBudget) return;
  ++stats.prefetchVisited;
  if (!fullyVisible) {
    const HorizonVisibility h = ctx.horizon.classify(b);
    if (h == HorizonVisibility::kHidden) return;
    fullyVisible = h == HorizonVisibility::kFullyVisible;
  }
  const int depth = id.level;
  if (depth == 0 && !ctx.residency->isResidentForPrefetch(id)) {
    ctx.residency->request(id, RequestPriority::kPrefetch, distanceToBounds(b, ctx.camera));
    ++stats.prefetchRequests;
    return;
  }
  if (depth >= ctx.maxDepth) return;
  const double range = ranges_.refineRangeOver(id) * config_.prefetch.ringRangeFactor;
  if (!intersectsSphere(b, ctx.camera, range)) return;
  if (!prefetchChildren(id, distanceToBounds(b, ctx.camera), ctx)) return;
  std::array<RadiusRange, 4> childRadius;
  for (size_t q = 0; q < 4; ++q) {
    childRadius[q] = ctx.residency->knownRadiusRange(id.child(static_cast<int>(q))).value_or(defaultRange_);
  }
  const std::array<NodeBounds, 4> bounds = childBounds(*mapping_, id, b, childRadius, shape_);
  for (size_t q = 0; q < 4; ++q) prefetchVisit(id.child(static_cast<int>(q)), bounds[q], fullyVisible, ctx);
}

}  // namespace globe
