#version 450
// Elevation at a batch of unit directions, in double: the GPU side of the CPU-reference test and
// of the samples-per-second benchmark (engine/generation/elevation_sampler.h), and the heights of
// `globe bake` (engine/bake/height_sampler.h). A planet with [[sources]] gives each direction its
// source term (binding 3, computed on the CPU as for payloads: elevation_sources.glsl); directions
// whose w is 0 have none (a procedural planet binds a 32-byte dummy).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "include/elevation_params.h"
// A uniform buffer, not a storage buffer: on lavapipe (Mesa 22.3) a storage-buffer load at a
// non-constant offset costs ~100 cycles per 8 lanes (apparently lane by lane, with bounds checks)
// and the layer loop reads ~12 parameters per layer; as a uniform buffer the 12-octave earthlike
// kernel measured ~1.4x faster (docs/elevation.md, "GPU compute path").
layout(std140, binding = 0) uniform Elevation { ElevationParams elevation; };
layout(std430, binding = 1) readonly buffer Directions { dvec4 directions[]; };  // xyz unit, w: 1 = has a source term
layout(std430, binding = 2) writeonly buffer Heights { double heights[]; };      // metres
#include "include/payload_layout.h"  // GLOBE_NO_SOURCE_TERMS
layout(push_constant) uniform Push { uint count; } push;

#define GLOBE_ELEVATION_PARAMS elevation
#include "include/elevation.glsl"
#define GLOBE_SOURCE_TERMS_BINDING 3
#include "include/elevation_sources.glsl"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  // The branch reads a storage buffer, never a push constant (no new lavapipe variant).
  uint sourceBase = directions[i].w != 0.0lf ? 0u : GLOBE_NO_SOURCE_TERMS;
  heights[i] = globeApplySources(globeElevation(directions[i].xyz), sourceBase, i);
}
