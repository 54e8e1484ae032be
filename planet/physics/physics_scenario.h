#pragma once
// Bodies for `globe physics`, the tests and the benchmark: dropped at the drop sites from a random
// height above the exact ground, and what a run reports per body (the columns of bodies.csv).
#include "planet/model/elevation_model.h"
#include "planet/physics/drop_sites.h"
#include "planet/physics/physics_simulation.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace globe {

enum class ShapeMix : uint8_t { kSphere, kBox, kMixed };
// "sphere", "box", "mixed" (spheres, boxes and capsules in turn); nullopt for anything else.
std::optional<ShapeMix> shapeMixFromName(std::string_view name);

struct ScenarioSettings {
  uint32_t bodies = 100;
  uint64_t seed = 1;
  ShapeMix shapes = ShapeMix::kMixed;
  bool clustered = false;  // all within clusterRadius_m of clusterCentre instead of scattered
  glm::dvec3 clusterCentre{1.0, 0.0, 0.0};
  double clusterRadius_m = 100.0;
  double minDrop_m = 1.0, maxDrop_m = 100.0;  // lowest point above the exact ground at the start
  double minSize_m = 0.5, maxSize_m = 2.0;
  double downwardSpeed_m_s = 0.0;  // initial speed towards the centre (impact tests)
};

struct PlacedBody {
  DropSite site;
  BodySpec spec;
  double startHeight_m = 0.0;  // lowest point above the exact surface at the start
};

// About how many collision meshes of `level` the bodies need at once, for sizing a run before it
// starts: each body's reach (its interest radius and largest size) covered by nodes of the nominal
// width, a cluster's disk once, never more than the level has. An underestimate near the real count
// (1000 scattered bodies at level 14, radius 8 m: 1100 against 1609 loaded), so a pool smaller than
// it surely thrashes.
struct CollisionMeshEstimate {
  double perBody = 0.0;
  double total = 0.0;
};
CollisionMeshEstimate estimateCollisionMeshes(const ScenarioSettings& settings, int level, double interestRadius_m,
                                              double planetRadius_m);

// Deterministic for the settings (seed included).
std::vector<PlacedBody> placeBodies(const ElevationModel& model, const ScenarioSettings& settings);

// Adds the bodies to the simulation (ids in order) and records their start heights.
void addPlacedBodies(PhysicsSimulation& simulation, const ElevationModel& model, std::vector<PlacedBody>& placed);

// Height of the lowest of `points` above the exact surface below it (negative: under the ground).
double clearanceAboveExact(const ElevationModel& model, std::span<const glm::dvec3> points);

struct BodyReport {
  uint32_t id = 0;
  double latitude_deg = 0.0, longitude_deg = 0.0;  // where the body is at the end
  BodyShape shape = BodyShape::kSphere;
  double size_m = 0.0;
  double startHeight_m = 0.0;
  double restHeight_m = 0.0;  // lowest point above the exact surface at the end
  double speed_m_s = 0.0;
  uint32_t contactNodes = 0;
  DropSiteKind site = DropSiteKind::kRandom;
};

std::vector<BodyReport> reportBodies(const ElevationModel& model, const PhysicsWorld& world,
                                     std::span<const PlacedBody> placed);

// bodies.csv: id,lat_deg,lon_deg,shape,size_m,start_height_m,rest_height_above_exact_surface_m,
// speed_m_s,contact_nodes — one line per body.
std::string formatBodiesCsv(std::span<const BodyReport> bodies);

}  // namespace globe
