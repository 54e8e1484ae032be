#pragma once
// How far a level-L collision mesh (= the drawn mesh at that level) is from the exact surface: the
// relief finer than its samples, which no body resting on the mesh can follow. Bodies rest on the
// mesh, so their height above the exact surface is within this error (docs/physics.md).
#include "planet/model/elevation_model.h"

#include <glm/vec3.hpp>

#include <cstdint>

namespace globe {

// Largest |drawn - exact| radius (metres) over a 9 x 9 grid of directions spanning `arc_m` around
// the unit direction `centre` (a body's footprint).
double meshErrorNear(const ElevationModel& model, const glm::dvec3& centre, double arc_m, int level, uint32_t cells);

struct MeshErrorStats {
  double p50_m = 0.0, p99_m = 0.0, max_m = 0.0;  // of |drawn - exact| at uniform random directions
  double meanSigned_m = 0.0;                     // mean of drawn - exact
  uint32_t samples = 0;
};

MeshErrorStats measureMeshError(const ElevationModel& model, int level, uint32_t cells, uint32_t samples,
                                uint64_t seed);

}  // namespace globe
