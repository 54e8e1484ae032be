// globe physics: drops bodies on the planet's collision meshes (docs/physics.md) and reports where
// they came to rest: DIR/bodies.csv, DIR/summary.json and optionally a rendered frame.
#include "commands.h"
#include "engine/collision/body_overlay.h"
#include "engine/collision/gpu_collision_mesh_source.h"
#include "engine/report/run_environment.h"
#include "options.h"
#include "planet/analysis/percentile.h"
#include "planet/analysis/terrain_queries.h"
#include "planet/core/atomic_file.h"
#include "planet/elevation/planet_file.h"
#include "planet/physics/mesh_error.h"
#include "planet/physics/physics_scenario.h"
#include "render_terrain.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace globe::cli {

namespace {

struct PhysicsOptions {
  DeviceFlags device;
  std::string planet;
  uint32_t bodies = 100;
  double seconds = 10.0;
  int level = 14;
  double radius_m = 8.0;
  int64_t seed = 1;  // >= 0 (signed, so that a negative value is refused rather than wrapped)
  std::string shape = "mixed";
  std::string out = "out/physics";
  std::string render;  // empty: no frame
  uint32_t gridCells = 32;
  bool clustered = false;
  double budget_MiB = 256.0;
};

struct PhysicsInputs {
  PlanetDescription planet;
  SimulationSettings simulation;
  ScenarioSettings scenario;
  uint64_t steps = 0;
};

Result<PhysicsInputs> checkInputs(const PhysicsOptions& o) {
  PhysicsInputs in;
  if (o.bodies < 1 || o.bodies > 100000) return Error::inField("--bodies", "must be within [1, 100000]");
  if (!(std::isfinite(o.seconds) && o.seconds > 0.0 && o.seconds <= 3600.0))
    return Error::inField("--seconds", "must be within (0, 3600]");
  if (o.level < 1 || o.level > 24) return Error::inField("--level", "must be within [1, 24]");
  if (!(std::isfinite(o.radius_m) && o.radius_m >= 0.0 && o.radius_m <= 10000.0))
    return Error::inField("--radius", "must be within [0, 10000] metres");
  if (o.gridCells < 16 || o.gridCells > 256 || (o.gridCells & (o.gridCells - 1)) != 0)
    return Error::inField("--grid", "must be a power of two in [16, 256]");
  if (o.seed < 0) return Error::inField("--seed", "must be >= 0");
  auto shapes = shapeMixFromName(o.shape);
  if (!shapes) return Error::inField("--shape", "must be sphere, box or mixed");
  if (auto s = checkOutputDirectory(o.out, "--out"); !s) return s.error();
  if (!o.render.empty()) {
    if (auto s = checkImageExtension(o.render, "--render"); !s) return s.error();
    if (auto s = checkWritable(o.render, "--render"); !s) return s.error();
  }
  auto planet = loadPlanetFile(o.planet);
  if (!planet) return planet.error();
  in.planet = std::move(*planet);
  in.simulation.level = o.level;
  in.simulation.interestRadius_m = o.radius_m;
  in.simulation.physics.surfaceGravity_m_s2 = in.planet.surface_gravity_m_s2;
  in.simulation.pool.budget_MiB = o.budget_MiB;
  if (auto s = validateSimulationSettings(in.simulation); !s) {
    Error e = s.error();
    e.field = e.field == "budget_MiB" ? "--budget" : "--" + e.field;
    return e;
  }
  in.scenario.bodies = o.bodies;
  in.scenario.seed = uint64_t(o.seed);
  in.scenario.shapes = *shapes;
  in.scenario.clustered = o.clustered;
  in.steps = uint64_t(std::llround(o.seconds / in.simulation.physics.step_s));
  return in;
}

// The lowest valley near the cluster's default place (lat 10, lon 20): the lowest of a coarse grid.
glm::dvec3 valleyNear(const ElevationModel& model) {
  glm::dvec3 best = directionFromLatLon(10.0, 20.0);
  double lowest = model.elevation_m(best);
  for (int a = -10; a <= 10; ++a)
    for (int b = -10; b <= 10; ++b) {
      const glm::dvec3 d = directionFromLatLon(10.0 + 0.002 * a, 20.0 + 0.002 * b);
      if (const double e = model.elevation_m(d); e < lowest) lowest = e, best = d;
    }
  return best;
}

double percentileOf(std::vector<double> values, uint32_t percent) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return nearestRankPercentile(values, percent);
}

std::string summaryJson(const PhysicsSimulation& sim, const GpuCollisionMeshSource& source,
                        std::span<const BodyReport> bodies, const MeshErrorStats& meshError, double wall_s) {
  const SimulationStats& s = sim.stats();
  const CollisionPoolStats& pool = sim.pool().stats();
  uint32_t atRest = 0, asleep = 0;
  double worstRest = 0.0, fastest = 0.0;
  for (const BodyReport& b : bodies) {
    asleep += sim.world().state(b.id).sleeping ? 1u : 0u;
    atRest += b.speed_m_s < 0.05 ? 1u : 0u;
    worstRest = std::max(worstRest, std::abs(b.restHeight_m));
    fastest = std::max(fastest, b.speed_m_s);
  }
  const double stepMax = s.step_ms.empty() ? 0.0 : *std::max_element(s.step_ms.begin(), s.step_ms.end());
  const uint64_t generated = pool.generatedSync + pool.generatedAsync;
  return fmt::format(
      "{{\n  \"bodies\": {},\n  \"steps\": {},\n  \"step_s\": {},\n  \"level\": {},\n  \"grid_cells\": {},\n"
      "  \"ms_per_step_p50\": {:.4f},\n  \"ms_per_step_p99\": {:.4f},\n  \"ms_per_step_max\": {:.4f},\n"
      "  \"physics_ms_per_step_p50\": {:.4f},\n  \"physics_ms_per_step_p99\": {:.4f},\n"
      "  \"cpu_ms_per_step_p50\": {:.4f},\n  \"cpu_ms_per_step_p99\": {:.4f},\n  \"cpu_ms_per_step_max\": {:.4f},\n"
      "  \"physics_cpu_ms_per_step_p50\": {:.4f},\n  \"physics_cpu_ms_per_step_p99\": {:.4f},\n"
      "  \"nodes_generated_sync\": {},\n  \"nodes_generated_async\": {},\n  \"nodes_evicted\": {},\n"
      "  \"predicted_contacts\": {},\n  \"gpu_ms_per_node\": {:.4f},\n  \"selection_ms_per_round\": {:.4f},\n"
      "  \"collision_pool_mib\": {:.3f},\n  \"collision_pool_budget_mib\": {:.3f},\n  \"resident_meshes\": {},\n"
      "  \"bodies_at_rest\": {},\n  \"bodies_asleep\": {},\n  \"max_speed_m_s\": {:.5f},\n  \"max_abs_rest_height_m\": "
      "{:.4f},\n"
      "  \"mesh_error_m\": {{\"p50\": {:.4f}, \"p99\": {:.4f}, \"max\": {:.4f}, \"samples\": {}}},\n"
      "  \"wall_s\": {:.3f},\n  \"load_average\": \"{}\"\n}}\n",
      bodies.size(), s.steps, sim.settings().physics.step_s, sim.settings().level, source.cells(),
      percentileOf(s.step_ms, 50), percentileOf(s.step_ms, 99), stepMax, percentileOf(s.physics_ms, 50),
      percentileOf(s.physics_ms, 99), percentileOf(s.stepCpu_ms, 50), percentileOf(s.stepCpu_ms, 99),
      percentileOf(s.stepCpu_ms, 100), percentileOf(s.physicsCpu_ms, 50), percentileOf(s.physicsCpu_ms, 99),
      pool.generatedSync, pool.generatedAsync, pool.evicted, s.predictedContacts,
      generated ? source.gpuTime_ms() / double(source.nodesGenerated()) : 0.0,
      s.selectionRounds ? s.selection_ms / double(s.selectionRounds) : 0.0, pool.residentMiB(),
      double(sim.pool().budgetBytes()) / (1024.0 * 1024.0), pool.resident, atRest, asleep, fastest, worstRest,
      meshError.p50_m, meshError.p99_m, meshError.max_m, meshError.samples, wall_s, loadAverage());
}

// A frame looking down at the first body from 25 m, with the bodies drawn in.
Result<ImageRgba> renderBodies(vk::Device& device, const ElevationModel& model, const PhysicsInputs& in,
                               const PhysicsWorld& world, uint32_t cells) {
  auto settings = terrainSettingsFromOptions({"", cells, 0}, in.planet, 720);
  if (!settings) return settings.error();
  const glm::dvec2 latLon = latLonFromPosition(world.state(0).position_m);
  const GeodeticPose pose{latLon.x - 0.0002, latLon.y, 25.0, 0.0, -50.0, 0.0};
  const glm::dvec3 down = directionFromLatLon(pose.latitude_deg, pose.longitude_deg);
  const double ground = TerrainQueries(model).cameraFloorRadius(down, settings->ranges.maxDepth, cells);
  const Camera camera = cameraFromPose(pose, ground, model.radius_m(), 16.0 / 9.0);
  auto image = renderTerrain(device, camera, model, in.planet, *settings, 960, 540);
  if (!image) return image.error();
  std::printf("%u bodies in view\n", drawBodies(*image, camera, world));
  return image;
}

int runPhysics(const PhysicsOptions& o) {
  auto in = checkInputs(o);
  if (!in) return usageError(in.error());
  const auto start = std::chrono::steady_clock::now();
  const ElevationModel model(in->planet);
  if (in->scenario.clustered) in->scenario.clusterCentre = valleyNear(model);
  vk::Device device(deviceOptions(o.device));
  GpuCollisionMeshSource source(device, model, o.gridCells, in->simulation.pool.maxInFlight);
  PhysicsSimulation sim(model, source, in->simulation);
  std::vector<PlacedBody> placed = placeBodies(model, in->scenario);
  addPlacedBodies(sim, model, placed);
  for (uint64_t s = 0; s < in->steps; ++s) sim.step();
  const std::vector<BodyReport> bodies = reportBodies(model, sim.world(), placed);
  const MeshErrorStats meshError = measureMeshError(model, o.level, o.gridCells, 2000, uint64_t(o.seed));
  std::optional<ImageRgba> frame;
  if (!o.render.empty()) {
    auto image = renderBodies(device, model, *in, sim.world(), o.gridCells);
    if (!image) return usageError(image.error());
    frame = std::move(*image);
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec) {
    printError(Error::inField("--out", "cannot create '" + o.out + "': " + ec.message()).format());
    return kExitFailure;
  }
  const NamedContent files[] = {{"bodies.csv", formatBodiesCsv(bodies)},
                                {"summary.json", summaryJson(sim, source, bodies, meshError, wall_s)}};
  if (auto s = writeFilesAtomically(o.out, files); !s) {
    printError(s.error().format());
    return kExitFailure;
  }
  if (frame) {
    if (auto s = writeImage(o.render, *frame, "--render"); !s) {
      printError(s.error().format());
      return kExitFailure;
    }
  }
  if (int code = validationExitCode(device); code != kExitOk) return code;
  std::printf("%zu bodies, %llu steps, %.1f s; wrote %s/bodies.csv and %s/summary.json\n", bodies.size(),
              (unsigned long long)sim.stats().steps, wall_s, o.out.c_str(), o.out.c_str());
  return kExitOk;
}

}  // namespace

void addPhysicsCommand(CLI::App& app, Runner& run) {
  auto opts = std::make_shared<PhysicsOptions>();
  opts->planet = defaultPlanetPath();
  CLI::App* cmd = app.add_subcommand("physics", "Drop rigid bodies on the collision meshes and report where they rest");
  cmd->add_option("--planet", opts->planet, "Planet file (TOML)")->capture_default_str();
  cmd->add_option("--bodies", opts->bodies, "Number of bodies (face seams, the 32 vertices, poles, ±180° first)")
      ->capture_default_str();
  cmd->add_option("--seconds", opts->seconds, "Simulated time (s), in fixed steps of 1/120 s")->capture_default_str();
  cmd->add_option("--level", opts->level, "Quadtree level of the collision meshes")->capture_default_str();
  cmd->add_option("--radius", opts->radius_m, "Radius of interest around each body (m)")->capture_default_str();
  cmd->add_option("--seed", opts->seed, "Seed of the random places, heights, sizes")->capture_default_str();
  cmd->add_option("--shape", opts->shape, "sphere, box or mixed (spheres, boxes, capsules)")->capture_default_str();
  cmd->add_option("--out", opts->out, "Output directory (bodies.csv, summary.json)")->capture_default_str();
  cmd->add_option("--render", opts->render, "Also render a frame with the bodies drawn (.png or .exr)");
  cmd->add_option("--grid", opts->gridCells, "Cells per node side of the collision meshes")->capture_default_str();
  cmd->add_flag("--clustered", opts->clustered, "All bodies within 100 m in one valley instead of scattered");
  cmd->add_option("--budget", opts->budget_MiB, "Collision-mesh pool budget (MiB)")->capture_default_str();
  addDeviceFlags(*cmd, opts->device);
  cmd->callback([opts, &run] { run = [opts] { return runPhysics(*opts); }; });
}

}  // namespace globe::cli
