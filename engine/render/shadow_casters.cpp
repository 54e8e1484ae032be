#include "engine/render/shadow_casters.h"

#include <algorithm>
#include <vector>

namespace globe {
namespace {

// What the caster selection asks of the pool: residency as the look-ahead does (nothing is marked
// wanted), and no requests.
class ResidentOnly final : public NodeResidency {
 public:
  explicit ResidentOnly(const NodeResidency& pool) : pool_(pool) {}
  bool isResident(const NodeId& node) const override { return pool_.isResidentForPrefetch(node); }
  bool isResidentForPrefetch(const NodeId& node) const override { return pool_.isResidentForPrefetch(node); }
  void request(const NodeId&, RequestPriority, double) override {}
  std::optional<RadiusRange> knownRadiusRange(const NodeId& node) const override {
    return pool_.knownRadiusRange(node);
  }
  std::optional<double> knownGeometricError(const NodeId& node) const override {
    return pool_.knownGeometricError(node);
  }

 private:
  const NodeResidency& pool_;
};

}  // namespace

void selectShadowCasters(LodSelector& selector, const Camera& camera, const Frustum& view, const glm::dvec3& sun,
                         double reach_m, int maxDepth, uint32_t maxNodes, const NodeResidency& residency,
                         Selection& out) {
  out.nodes.clear();
  out.stats = {};
  // The camera's frustum swept towards the sun: a plane whose inside the sweep moves points into
  // (n . sun >= 0) still bounds it; the others are crossed and left out. Then a bound towards the
  // sun: casters within reach_m of the camera's receivers' reach.
  std::vector<glm::dvec4> planes;
  for (const glm::dvec4& p : view.planes())
    if (glm::dot(glm::dvec3(p), sun) >= 0.0) planes.push_back(p);
  planes.push_back(glm::dvec4(-sun, glm::dot(sun, camera.position_m) + 2.0 * reach_m));
  if (planes.size() > 6) return;
  auto swept = Frustum::fromPlanes(planes);
  if (!swept) return;
  ResidentOnly resident(residency);
  if (!selector.select({camera.position_m, &*swept, maxDepth, maxNodes}, resident, out)) {
    out.nodes.clear();
    return;
  }
  std::erase_if(out.nodes, [&](const SelectedNode& n) {
    return view.classify(selector.boundsFor(n.id, residency)) != Containment::kOutside;
  });
}

}  // namespace globe
