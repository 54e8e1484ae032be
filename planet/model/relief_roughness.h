#pragma once
// Where a planet's procedural relief is rough, per LOD depth (a RoughnessMap for LodRanges'
// tolerance-driven ranges, docs/lod.md "Roughness"). The model, per layer and depth d: the error of
// drawing depth d instead of d + 1 — the largest midpoint deviation of each octave (wavelength L,
// amplitude a) at the depth-(d+1) vertex spacing h, a * (1 - cos(min(pi, 2 pi h / L))), summed over
// the layer's octaves — times the layer's modulation scale at the point, plus the sphere's own sag
// h^2 / (2 R). Over deep sea (drawn flat at sea level) only the sag counts. The absolute scale does
// not matter: LodRanges calibrates it against the payloads' measured errors.
#include <memory>

#include "planet/lod/roughness_map.h"
#include "planet/model/elevation_model.h"

namespace globe {

// nullptr for a planet with elevation sources (their relief is not modelled: per-depth ranges).
std::shared_ptr<const RoughnessMap> reliefRoughnessMap(const ElevationModel& model, int gridCells, int maxDepth);

}  // namespace globe
