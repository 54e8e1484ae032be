// Bodies on the collision meshes (planet/physics/physics_simulation.h), on the CPU reference of the
// payload kernel: they come to rest everywhere (vertices, poles, seams, ±180°), within the level's
// own mesh error of the exact surface, never fall through (also at 50 m/s), wait for a mesh only on
// a predicted contact, and the same seed gives the same run bit for bit.
#include "planet/camera/camera.h"
#include "planet/geometry/ellipsoid.h"
#include "planet/model/planet_file.h"
#include "planet/physics/mesh_error.h"
#include "planet/physics/physics_scenario.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <set>

namespace globe {
namespace {

constexpr int kLevel = 14;                // ~250 m nodes on the earthlike planet
constexpr uint32_t kCells = 32;           // the renderer's default grid
constexpr double kContactSlack_m = 0.05;  // Bullet's penetration at rest and rounding

const ElevationModel& testModel() {
  static const ElevationModel model(*loadPlanetFile(GLOBE_SOURCE_DIR "/assets/planets/earthlike.toml"));
  return model;
}

struct SimulationRun {
  std::unique_ptr<CpuCollisionMeshSource> source;
  std::unique_ptr<PhysicsSimulation> sim;
  std::vector<PlacedBody> placed;
};

SimulationRun startRun(const ScenarioSettings& scenario) {
  SimulationRun run;
  run.source = std::make_unique<CpuCollisionMeshSource>(testModel(), kCells);
  SimulationSettings settings;
  settings.level = kLevel;
  settings.interestRadius_m = 16.0;
  run.sim = std::make_unique<PhysicsSimulation>(testModel(), *run.source, settings);
  run.placed = placeBodies(testModel(), scenario);
  addPlacedBodies(*run.sim, testModel(), run.placed);
  return run;
}

// Lowest the body's centre may get: the exact ground minus the mesh error there, plus the part of
// the body below its centre that can never be under the mesh... simply half its smallest extent.
double centreFloor(const ElevationModel& model, const glm::dvec3& centre, double error_m, double halfSize_m) {
  const glm::dvec3 up = glm::normalize(centre);
  return model.radius_m() + model.elevation_m(up) - error_m - kContactSlack_m + 0.5 * halfSize_m;
}

void expectNoFallThrough(SimulationRun& run, uint32_t steps, const char* what) {
  const ElevationModel& model = testModel();
  std::vector<double> errors;
  for (uint32_t id = 0; id < run.sim->world().bodyCount(); ++id)
    errors.push_back(meshErrorNear(model, glm::normalize(run.sim->world().state(id).position_m),
                                   4.0 * run.sim->world().boundingRadius(id), kLevel, kCells));
  for (uint32_t s = 0; s < steps; ++s) {
    run.sim->step();
    for (uint32_t id = 0; id < run.sim->world().bodyCount(); ++id) {
      const glm::dvec3 p = run.sim->world().state(id).position_m;
      double floor = centreFloor(model, p, errors[id], 0.5 * run.sim->world().spec(id).size_m);
      if (glm::length(p) <= floor) {  // moved to where the mesh is farther from the exact surface?
        errors[id] = meshErrorNear(model, glm::normalize(p), 4.0 * run.sim->world().boundingRadius(id), kLevel, kCells);
        floor = centreFloor(model, p, errors[id], 0.5 * run.sim->world().spec(id).size_m);
      }
      // Through the mesh: then the mesh is above the body's centre, and a radial ray up hits it (a
      // height field is never above itself along the vertical).
      ASSERT_FALSE(run.sim->world().rayCastMeshes(p, glm::normalize(p), 2000.0))
          << what << ": body " << id << " (" << dropSiteKindName(run.placed[id].site.kind)
          << ") fell through a mesh at step " << s;
      ASSERT_GT(glm::length(p), floor) << what << ": body " << id << " (" << dropSiteKindName(run.placed[id].site.kind)
                                       << ") under the ground at step " << s;
    }
  }
}

TEST(PhysicsSimulation, BodiesComeToRestEverywhereWithinTheMeshError) {
  ScenarioSettings scenario;
  scenario.bodies = 64;  // the interleaved special places: poles, vertices, seams, ±180°; then random
  scenario.seed = 3;
  scenario.minDrop_m = 0.5;
  scenario.maxDrop_m = 4.0;
  SimulationRun run = startRun(scenario);
  expectNoFallThrough(run, 8 * 120, "dropped");
  const auto reports = reportBodies(testModel(), run.sim->world(), run.placed);
  std::set<DropSiteKind> kinds;
  for (const BodyReport& r : reports) {
    const BodyState state = run.sim->world().state(r.id);
    const double error = meshErrorNear(testModel(), glm::normalize(state.position_m), 2.0 * r.size_m, kLevel, kCells);
    EXPECT_LT(r.speed_m_s, 0.05) << "body " << r.id << " (" << dropSiteKindName(r.site) << ") still moving";
    EXPECT_LE(std::abs(r.restHeight_m), error + kContactSlack_m)
        << "body " << r.id << " (" << dropSiteKindName(r.site) << ", " << bodyShapeName(r.shape)
        << ") rests off the surface; mesh error there " << error << " m";
    EXPECT_GE(r.contactNodes, 1u) << "body " << r.id << " touches no mesh";
    kinds.insert(r.site);
  }
  EXPECT_EQ(kinds.size(), 4u) << "vertices, poles, seams, ±180°";
}

TEST(PhysicsSimulation, FiftyMetresPerSecondImpactsAtSeamsAndVerticesHold) {
  ScenarioSettings scenario;
  scenario.bodies = 60;
  scenario.seed = 11;
  scenario.minDrop_m = 2.0;
  scenario.maxDrop_m = 3.0;
  scenario.downwardSpeed_m_s = 50.0;
  SimulationRun run = startRun(scenario);
  expectNoFallThrough(run, 240, "50 m/s");
  EXPECT_GT(run.sim->pool().stats().generatedSync, 0u) << "contacts this close must be generated at once";
}

TEST(PhysicsSimulation, SynchronousGenerationOnlyForPredictedContacts) {
  ScenarioSettings high;
  high.bodies = 20;
  high.minDrop_m = 40.0;
  high.maxDrop_m = 60.0;
  SimulationRun run = startRun(high);
  for (int s = 0; s < 600; ++s) run.sim->step();
  EXPECT_EQ(run.sim->pool().stats().generatedSync, 0u) << "bodies starting 40 m up never wait for a mesh";
  EXPECT_GT(run.sim->pool().stats().generatedAsync, 0u);
  EXPECT_GT(run.sim->stats().predictedContacts, 0u);

  ScenarioSettings low = high;
  low.minDrop_m = 0.05;
  low.maxDrop_m = 0.1;
  SimulationRun closeRun = startRun(low);
  for (int s = 0; s < 60; ++s) closeRun.sim->step();
  EXPECT_GT(closeRun.sim->pool().stats().generatedSync, 0u);
  EXPECT_EQ(closeRun.sim->pool().stats().generatedSync, closeRun.sim->stats().predictedMissing)
      << "every synchronous generation is a predicted contact's missing node";
}

// Bodies 0 and 1 start in different Bullet worlds (id % 2); one dropped onto the other must still
// land on it: the grouping moves them into one world before they meet.
TEST(PhysicsSimulation, BodiesInSeparateWorldsStillCollide) {
  CpuCollisionMeshSource source(testModel(), kCells);
  SimulationSettings settings;
  settings.level = kLevel;
  ASSERT_EQ(settings.physics.worlds, 2u);
  PhysicsSimulation sim(testModel(), source, settings);
  const glm::dvec3 up = directionFromLatLon(12.0, 34.0);
  const double ground_m = testModel().radius_m() + testModel().elevation_m(up);
  BodySpec lower;
  lower.shape = BodyShape::kBox;
  lower.position_m = up * (ground_m + 0.5);
  BodySpec upper = lower;
  upper.position_m = up * (ground_m + 6.0);
  sim.addBody(lower);
  sim.addBody(upper);
  sim.settleSelection();
  for (int s = 0; s < 180; ++s) sim.step();  // the upper box lands after ~1 s
  const double gap_m = glm::length(sim.world().state(1).position_m) - glm::length(sim.world().state(0).position_m);
  EXPECT_GT(gap_m, 0.8) << "the upper box passed through the lower one";
}

TEST(PhysicsSimulation, DeterministicForASeed) {
  ScenarioSettings scenario;
  scenario.bodies = 24;
  scenario.seed = 5;
  scenario.maxDrop_m = 5.0;
  auto positions = [&] {
    SimulationRun run = startRun(scenario);
    for (int s = 0; s < 240; ++s) run.sim->step();
    std::vector<glm::dvec3> out;
    for (uint32_t id = 0; id < run.sim->world().bodyCount(); ++id) out.push_back(run.sim->world().state(id).position_m);
    return out;
  };
  const auto a = positions(), b = positions();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::dvec3)), 0);
}

// A body falling in open air on an ellipsoid (f = 0.1, far flatter than any planet) falls along the
// geodetic normal of the ground below it, not at the centre (6 degrees apart at 45 degrees), so a body
// at rest on level ground is not pulled sideways; on a sphere, radially.
TEST(PhysicsWorld, GravityFollowsTheEllipsoidsNormal) {
  for (const double flattening : {0.0, 0.1}) {
    const Ellipsoid shape = *Ellipsoid::create(6378137.0, flattening);
    PhysicsSettings settings;
    settings.planetRadius_m = shape.equatorialRadius_m();
    settings.flattening = flattening;
    PhysicsWorld world(settings);
    BodySpec body;
    body.position_m = shape.geocentricFromGeodetic({45.0, 30.0, 1000.0});
    world.addBody(body);
    for (int s = 0; s < 120; ++s) world.step();  // 1 s, no meshes: free fall
    const glm::dvec3 fall = glm::normalize(world.state(0).velocity_m_s);
    const glm::dvec3 normal = shape.normalBelow(body.position_m);
    const glm::dvec3 radial = glm::normalize(body.position_m);
    EXPECT_GT(glm::dot(fall, -normal), std::cos(1e-4)) << "f = " << flattening;
    if (flattening > 0.0) {
      EXPECT_LT(glm::dot(fall, -radial), std::cos(0.05));
    }
    // g (a / r)^2 for 1 s, less up to 5 % of linear damping (0.05 per second).
    const double g =
        settings.surfaceGravity_m_s2 * std::pow(shape.equatorialRadius_m() / glm::length(body.position_m), 2);
    EXPECT_NEAR(glm::length(world.state(0).velocity_m_s), 0.975 * g, 0.03 * g);
  }
}

}  // namespace
}  // namespace globe
