#pragma once
// The shadow maps' casters beyond the view (engine/render/terrain_shadows.h): relief outside the
// camera's frustum that may shade what it sees — behind the camera with the sun ahead, beside the
// view with a low sun. A second selection with the camera's LOD ranges over the camera's frustum
// swept towards the sun (its planes the sweep does not cross, and a bound as far towards the sun as
// shadows are drawn), of resident nodes only: it requests nothing and pins nothing; a node not resident is
// stood in for by its resident ancestor. Only the nodes outside the camera's frustum are kept: the
// ones in view are the drawn nodes themselves, whose meshes the receivers must meet exactly.
#include "planet/camera/camera.h"
#include "planet/lod/frustum.h"
#include "planet/lod/selection.h"

namespace globe {

// `reach_m`: how far from the camera shadows are drawn (the last cascade's reach), which bounds the
// sweep. Fills `out` (cleared first) with the casters outside `view`; a degenerate camera or sun
// leaves it empty.
void selectShadowCasters(LodSelector& selector, const Camera& camera, const Frustum& view, const glm::dvec3& sun,
                         double reach_m, int maxDepth, uint32_t maxNodes, const NodeResidency& residency,
                         Selection& out);

}  // namespace globe
