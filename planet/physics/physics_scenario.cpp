#include "planet/physics/physics_scenario.h"

#include "planet/camera/camera.h"
#include "planet/lod/lod_ranges.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace globe {

std::optional<ShapeMix> shapeMixFromName(std::string_view name) {
  if (name == "sphere") return ShapeMix::kSphere;
  if (name == "box") return ShapeMix::kBox;
  if (name == "mixed") return ShapeMix::kMixed;
  return std::nullopt;
}

namespace {

BodyShape shapeFor(ShapeMix mix, uint32_t index) {
  switch (mix) {
    case ShapeMix::kSphere:
      return BodyShape::kSphere;
    case ShapeMix::kBox:
      return BodyShape::kBox;
    case ShapeMix::kMixed:
      break;
  }
  constexpr BodyShape kTurns[3] = {BodyShape::kSphere, BodyShape::kBox, BodyShape::kCapsule};
  return kTurns[index % 3];
}

double boundingRadiusOf(BodyShape shape, double size_m) {
  switch (shape) {
    case BodyShape::kSphere:
      return 0.5 * size_m;
    case BodyShape::kBox:
      return 0.5 * size_m * std::sqrt(3.0);
    case BodyShape::kCapsule:
      return size_m;
  }
  return size_m;
}

glm::dquat randomOrientation(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  glm::dquat q(n(rng), n(rng), n(rng), n(rng));
  return glm::normalize(q);
}

}  // namespace

CollisionMeshEstimate estimateCollisionMeshes(const ScenarioSettings& settings, int level, double interestRadius_m,
                                              double planetRadius_m) {
  const double width_m = nominalNodeWidth(level, planetRadius_m);
  const auto nodesAcross = [width_m](double radius_m) {
    const double n = 2.0 * radius_m / width_m + 1.0;
    return n * n;
  };
  const double reach_m = interestRadius_m + settings.maxSize_m;
  CollisionMeshEstimate e;
  e.perBody = nodesAcross(reach_m);
  e.total = double(settings.bodies) * e.perBody;
  if (settings.clustered) e.total = std::min(e.total, nodesAcross(settings.clusterRadius_m + reach_m));
  e.total = std::min(e.total, 30.0 * std::pow(4.0, level));  // the level's nodes
  return e;
}

std::vector<PlacedBody> placeBodies(const ElevationModel& model, const ScenarioSettings& settings) {
  std::mt19937_64 rng(settings.seed);
  const std::vector<DropSite> sites =
      settings.clustered
          ? clusteredDropSites(settings.bodies, settings.clusterCentre, settings.clusterRadius_m, model.radius_m(), rng)
          : scatteredDropSites(settings.bodies, rng);
  std::uniform_real_distribution<double> drop(settings.minDrop_m, settings.maxDrop_m);
  std::uniform_real_distribution<double> size(settings.minSize_m, settings.maxSize_m);
  std::vector<PlacedBody> out;
  out.reserve(sites.size());
  for (uint32_t k = 0; k < sites.size(); ++k) {
    PlacedBody b;
    b.site = sites[k];
    b.spec.shape = shapeFor(settings.shapes, k);
    b.spec.size_m = size(rng);
    const double height = drop(rng);
    b.spec.orientation = randomOrientation(rng);
    // The centre above the highest ground under the body's footprint (a 3x3 probe), so the lowest
    // point starts at least `height` above the exact surface.
    const double extent = boundingRadiusOf(b.spec.shape, b.spec.size_m);
    const glm::dvec3 up = b.site.direction;
    const auto [east, north] = tangentFrame(up);
    double ground = -std::numeric_limits<double>::infinity();
    for (int a = -1; a <= 1; ++a)
      for (int c = -1; c <= 1; ++c) {
        const glm::dvec3 d = glm::normalize(up * model.radius_m() + (double(a) * east + double(c) * north) * extent);
        ground = std::max(ground, model.radius_m() + model.elevation_m(d));
      }
    // On an ellipsoid `up` is the geodetic normal and `ground` is a + the highest ellipsoidal height.
    b.spec.position_m = model.shape().isSphere()
                            ? up * (ground + height + extent)
                            : model.shape().position(up, ((ground - model.radius_m()) + height) + extent);
    b.spec.velocity_m_s = -up * settings.downwardSpeed_m_s;
    out.push_back(b);
  }
  return out;
}

void addPlacedBodies(PhysicsSimulation& simulation, const ElevationModel& model, std::vector<PlacedBody>& placed) {
  for (PlacedBody& b : placed) {
    const uint32_t id = simulation.addBody(b.spec);
    b.startHeight_m = clearanceAboveExact(model, simulation.world().surfacePoints(id));
  }
}

double clearanceAboveExact(const ElevationModel& model, std::span<const glm::dvec3> points) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const glm::dvec3& p : points) lowest = std::min(lowest, model.heightAboveTerrain_m(p));
  return lowest;
}

std::vector<BodyReport> reportBodies(const ElevationModel& model, const PhysicsWorld& world,
                                     std::span<const PlacedBody> placed) {
  std::vector<BodyReport> out;
  for (uint32_t id = 0; id < world.bodyCount(); ++id) {
    const BodyState state = world.state(id);
    const GeodeticPoint g = model.shape().geodeticFromGeocentric(state.position_m);
    const glm::dvec2 latLon =
        model.shape().isSphere() ? latLonFromPosition(state.position_m) : glm::dvec2(g.latitude_deg, g.longitude_deg);
    const std::vector<glm::dvec3> points = world.surfacePoints(id);
    BodyReport r;
    r.id = id;
    r.latitude_deg = latLon.x;
    r.longitude_deg = latLon.y;
    r.shape = world.spec(id).shape;
    r.size_m = world.spec(id).size_m;
    r.startHeight_m = id < placed.size() ? placed[id].startHeight_m : 0.0;
    r.restHeight_m = clearanceAboveExact(model, points);
    r.speed_m_s = glm::length(state.velocity_m_s);
    r.contactNodes = uint32_t(world.contactNodes(id).size());
    r.site = id < placed.size() ? placed[id].site.kind : DropSiteKind::kRandom;
    out.push_back(r);
  }
  return out;
}

std::string formatBodiesCsv(std::span<const BodyReport> bodies) {
  std::string out =
      "id,lat_deg,lon_deg,shape,size_m,start_height_m,rest_height_above_exact_surface_m,speed_m_s,contact_nodes\n";
  for (const BodyReport& b : bodies)
    out += fmt::format("{},{:.9f},{:.9f},{},{:.4f},{:.4f},{:.4f},{:.5f},{}\n", b.id, b.latitude_deg, b.longitude_deg,
                       bodyShapeName(b.shape), b.size_m, b.startHeight_m, b.restHeight_m, b.speed_m_s, b.contactNodes);
  return out;
}

}  // namespace globe
