#include "planet/streaming/frame_budget.h"

#include "planet/lod/lod_ranges.h"
#include "planet/streaming/payload_pool.h"

#include <algorithm>
#include <cmath>

namespace globe {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

Status validateFrameBudget(const FrameBudget& b, uint64_t trianglesPerNode) {
  if (b.maxDrawnNodes < 30) return Error::inField("max_drawn_nodes", "must be >= 30 (the roots)");
  if (b.maxTriangles / std::max<uint64_t>(trianglesPerNode, 1) < 30)
    return Error::inField("max_triangles", "must allow the 30 roots: at least " +
                                               std::to_string(30 * trianglesPerNode) + " at this grid");
  if (b.maxRequests < 2) return Error::inField("max_requests", "must be >= 2");
  return Ok{};
}

BudgetedSelection::BudgetedSelection(const FrameBudget& budget, uint64_t trianglesPerNode, int maxDepth)
    : budget_(budget),
      trianglesPerNode_(std::max<uint64_t>(trianglesPerNode, 1)),
      maxDepth_(maxDepth),
      nodeLimit_(uint32_t(std::min<uint64_t>(budget.maxDrawnNodes, budget.maxTriangles / trianglesPerNode_))),
      depthCap_(maxDepth) {
  requests_.reserve(budget.maxRequests);
}

int BudgetedSelection::deepestCapWithin(const LodSelector& selector, double nodes) const {
  // By the ranges alone: level k draws at most the nodes whose bounds can meet the ball of R(k-1)
  // around the camera, about pi (R(k-1) / w(k) + 2)^2 of width w(k), and never more than the level has.
  const double radius_m = selector.config().radius_m;
  double total = 0.0;
  for (int k = 0; k <= maxDepth_; ++k) {
    double level = 30.0 * std::pow(4.0, k);
    if (k > 0) {
      const double reach = selector.ranges().refineRange(k - 1) / nominalNodeWidth(k, radius_m) + 2.0;
      level = std::min(level, kPi * reach * reach);
    }
    total += level;
    if (total > nodes) return std::max(0, k - 1);
  }
  return maxDepth_;
}

Status BudgetedSelection::select(LodSelector& selector, SelectionCamera camera, PayloadPool& pool, Selection& out) {
  pool_ = &pool;
  camera.maxNodes = nodeLimit_;
  // Ranges that reach thousands of node widths at the deep levels (relief of 1e6 m grows them, see
  // LodRanges) would fill the budget many times over: cap at once, before those levels are generated
  // only to be found too large. The bound ignores the frustum and the horizon, so it is loose; 16
  // times the budget (two levels) keeps every ordinary view and preset far from it.
  const int plausible = deepestCapWithin(selector, 16.0 * nodeLimit_);
  if (plausible < depthCap_) {
    depthCap_ = plausible;
    warnLimited();
  }
  // Over budget: the same frame again one level coarser, until it fits (30 roots always do). Each
  // pass stops at the node limit, so a pass costs at most about that many nodes.
  for (;;) {
    requests_.clear();
    dropped_ = 0;
    camera.maxDepth = depthCap_;
    if (auto s = selector.select(camera, *this, out); !s) {
      pool_ = nullptr;
      return s;
    }
    if (!out.stats.overBudget || depthCap_ == 0) break;
    --depthCap_;
    warnLimited();
  }
  for (const Request& r : requests_) pool.request(r.node, r.priority, r.distance_m);
  pool_ = nullptr;
  // One level deeper turns each held-back node into at most four: raise the cap for the next frame
  // when that still fits. Nodes drawn in place of children still generating (fallbacks) will be
  // four nodes too, so they count the same: otherwise a view still streaming in would predict too
  // few and the cap would rise and fall, generating levels it then does not draw.
  const uint64_t streaming = uint64_t(out.nodes.size()) + 3 * uint64_t(out.stats.fallbacks);
  const uint64_t predicted = streaming + 3 * uint64_t(out.stats.heldBack);
  rising_ = depthCap_ < std::min(maxDepth_, plausible) && out.stats.heldBack > 0 && predicted <= nodeLimit_;
  if (rising_) {
    ++depthCap_;
  } else if (streaming > nodeLimit_ && depthCap_ > 0) {
    // What is still streaming in will not fit: one level coarser from the next frame, before the
    // levels it would not draw are generated (a planet that refines everywhere otherwise fills the
    // pool level by level on its way down to the cap that fits).
    --depthCap_;
    warnLimited();
  }
  return Ok{};
}

void BudgetedSelection::warnLimited() {
  if (!warning_.empty()) return;
  warning_ = "frame budget reached (" + std::to_string(budget_.maxDrawnNodes) + " nodes, " +
             std::to_string(budget_.maxTriangles) + " triangles): drawing coarser terrain (levels up to " +
             std::to_string(depthCap_) + " of " + std::to_string(maxDepth_) + ")";
}

bool BudgetedSelection::isResident(const NodeId& node) const { return pool_->isResident(node); }

bool BudgetedSelection::isResidentForPrefetch(const NodeId& node) const { return pool_->isResidentForPrefetch(node); }

std::optional<RadiusRange> BudgetedSelection::knownRadiusRange(const NodeId& node) const {
  return pool_->knownRadiusRange(node);
}

std::optional<double> BudgetedSelection::knownGeometricError(const NodeId& node) const {
  return pool_->knownGeometricError(node);
}

void BudgetedSelection::request(const NodeId& node, RequestPriority priority, double distance_m) {
  // Look-ahead gets at most half the requests, so what the view waits for always has room.
  const size_t limit = priority == RequestPriority::kPrefetch ? budget_.maxRequests / 2 : budget_.maxRequests;
  if (requests_.size() >= limit) {
    ++dropped_;
    return;
  }
  requests_.push_back({node, priority, distance_m});
}

}  // namespace globe
