// Real elevation sources in the payload and elevation-sample kernels (planet/sources, docs/elevation-data.md). The CPU's
// source I/O thread resolves the mosaic at every sample of a job (latitude/longitude, reprojection
// and bilinear lookups need double trigonometry and PROJ, which GLSL lacks) and uploads one
// dvec4 (height_m, weight, hole, 0) per sample; here the kernel only blends them over its own
// procedural elevation, with the CPU reference's expression (combineSourceTerm,
// planet/sources/source_mosaic.h), so GPU and CPU payloads agree to the procedural layers' 1e-6 m.
// Jobs with sourceBase == GLOBE_NO_SOURCE_TERMS (every job of a procedural planet) read nothing.
// The branch reads a storage buffer value, so it never makes lavapipe compile a new variant.

// The terms' binding: 6 in the payload kernel; a kernel with other bindings defines its own.
#ifndef GLOBE_SOURCE_TERMS_BINDING
#define GLOBE_SOURCE_TERMS_BINDING 6
#endif
layout(std430, binding = GLOBE_SOURCE_TERMS_BINDING) readonly buffer SourceTerms { dvec4 sourceTerms[]; };

// Elevation (metres) at sample `index` of a job whose terms start at `sourceBase`.
double globeApplySources(double procedural_m, uint sourceBase, uint index) {
  if (sourceBase == GLOBE_NO_SOURCE_TERMS) return procedural_m;
  dvec4 t = sourceTerms[sourceBase + index];
  precise double h = (1.0lf - t.y) * procedural_m + t.y * t.x;
  return h;
}

// The float kernel's blend (payload_generate_float.comp, `globe trade`'s fp32 comparison): the same
// expression in float, so a planet with sources is compared like with like.
float globeApplySourcesFloat(float procedural_m, uint sourceBase, uint index) {
  if (sourceBase == GLOBE_NO_SOURCE_TERMS) return procedural_m;
  vec2 t = vec2(sourceTerms[sourceBase + index].xy);
  return (1.0 - t.y) * procedural_m + t.y * t.x;
}

// Hole mask in [0, 1] at sample `index` (>= 0.5: a kept no-data hole; the fragment shader discards).
float globeSourceHole(uint sourceBase, uint index) {
  if (sourceBase == GLOBE_NO_SOURCE_TERMS) return 0.0;
  return float(sourceTerms[sourceBase + index].z);
}
