// Terrain queries (planet/analysis/terrain_queries.h): exact and drawn heights, rays against the
// exact surface and against collision meshes, and camera moves that never pass below the ground.
#include "planet/analysis/terrain_queries.h"
#include "planet/camera/camera.h"
#include "planet/model/planet_file.h"
#include "planet/physics/drop_sites.h"
#include "planet/physics/mesh_error.h"
#include "planet/physics/physics_world.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <random>

namespace globe {
namespace {

const ElevationModel& testModel() {
  static const ElevationModel model(*loadPlanetFile(GLOBE_SOURCE_DIR "/assets/planets/earthlike.toml"));
  return model;
}

TEST(TerrainQueries, DrawnHeightIsWithinTheMeasuredMeshError) {
  const TerrainQueries q(testModel());
  const MeshErrorStats error = measureMeshError(testModel(), 14, 32, 400, 1);
  std::mt19937_64 rng(2);
  for (const DropSite& s : scatteredDropSites(200, rng)) {
    const double drawn = q.drawnHeight_m(s.direction, 14, 32), exact = q.exactHeight_m(s.direction);
    EXPECT_LE(std::abs(drawn - exact), 3.0 * error.max_m + 0.01);
    EXPECT_GE(q.cameraFloorRadius(s.direction, 14, 32), testModel().radius_m() + std::max(drawn, exact) - 1e-6);
  }
  EXPECT_GT(error.max_m, 0.0);
}

// A camera 2 m above the ground thrown 20 km sideways in one frame (a fast fly-over at any speed):
// no point of the move is under the exact surface, and it ends above the camera floor.
TEST(TerrainQueries, GuardedMovesNeverPassBelowTheGround) {
  const ElevationModel& model = testModel();
  const TerrainQueries q(model);
  std::mt19937_64 rng(9);
  for (const DropSite& s : scatteredDropSites(24, rng)) {
    const glm::dvec3 from = s.direction * (model.radius_m() + model.elevation_m(s.direction) + 2.0);
    const auto [east, north] = tangentFrame(s.direction);
    const glm::dvec3 to = from + (east - 0.02 * s.direction) * 20000.0;
    const glm::dvec3 end = q.guardedMove(from, to, 0.01, 20, 32);
    for (int k = 0; k <= 2000; ++k) {
      const glm::dvec3 p = from + (end - from) * (k / 2000.0);
      const double r = glm::length(p);
      ASSERT_GE(r, model.radius_m() + model.elevation_m(p / r) - 1e-3) << "under the ground at " << k;
    }
    const glm::dvec3 up = glm::normalize(end);
    EXPECT_GE(glm::length(end), q.cameraFloorRadius(up, 20, 32) + 0.01 - 1e-6);
  }
}

TEST(TerrainQueries, RaysHitTheExactSurfaceAndTheCollisionMeshAlike) {
  const ElevationModel& model = testModel();
  const TerrainQueries q(model);
  CpuCollisionMeshSource source(model, 32);
  PhysicsWorld world(PhysicsSettings{});
  const glm::dvec3 up = directionFromLatLon(12.0, 34.0);
  const NodeId node = nodeAt(RhombusFaceMapping::get().locate(up), 14);
  const CollisionMesh mesh = source.generateNow(node);
  world.meshResident(mesh);
  const glm::dvec3 origin = up * (model.radius_m() + model.elevation_m(up) + 100.0);
  const auto exact = q.rayExact(origin, -up, 1000.0);
  const auto drawn = world.rayCastMeshes(origin, -up, 1000.0);
  ASSERT_TRUE(exact && drawn);
  EXPECT_NEAR(*exact, 100.0, 1e-3);
  EXPECT_LE(std::abs(*drawn - *exact), meshErrorNear(model, up, 1.0, 14, 32) + 1e-3);
  EXPECT_NEAR(*drawn, glm::length(origin) - q.drawnHeight_m(up, 14, 32) - model.radius_m(), 1e-3)
      << "the collision mesh is the drawn mesh";
  EXPECT_FALSE(q.rayExact(origin, up, 1000.0)) << "up: sky";
  EXPECT_FALSE(q.rayExact(origin, -up, 50.0)) << "beyond the maximum distance: nothing";
  world.meshEvicted(node);
  EXPECT_FALSE(world.rayCastMeshes(origin, -up, 1000.0));
}

}  // namespace
}  // namespace globe
