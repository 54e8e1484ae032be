// Face mapping of the rhombic triacontahedron, verbatim port of globe::RhombusFaceMapping
// (planet/geometry/face_mapping.{h,cpp}): (face corners, u, v) -> point on the flat rhombus -> unit sphere.
// Requires shaderFloat64 (GL_ARB_gpu_shader_fp64, implied by Vulkan GLSL with the feature enabled).
//
// Seam exactness: for dyadic u, v (k / 2^L) a point on a face edge is the same double from both faces
// and a vertex the same from all faces around it, because
//   * corners (u, v both 0 or 1) return the vertex itself,
//   * edge points are lerped from the endpoint with the LOWER vertex index, parameter measured from it,
//   * every intermediate is `precise` (no fused multiply-add, no reassociation).
// Exact operation order (must not change; the C++ side is the reference):
//   edge:      p = A + t * (B - A)                         per component
//   interior:  p = (c0 + u * (c1 - c0)) + v * (c3 - c0)    per component
//   unit:      s = 1.0 / sqrt((p.x * p.x + p.y * p.y) + p.z * p.z); p * s
// GPU double sqrt/division need not be correctly rounded, so GPU and CPU results may differ in the
// last bits; GPU-side points still agree bit-for-bit with each other across seams.
#ifndef GLOBE_FACE_MAPPING_GLSL
#define GLOBE_FACE_MAPPING_GLSL

// std430 layout of globe::FaceCornersGpu: xyz = flat corner (unit-sphere scale), w = vertex index
// (0..31). Corners counter-clockwise seen from outside: (u,v) = (0,0) (1,0) (1,1) (0,1).
struct FaceCorners {
  dvec4 corner[4];
};

// Point on edge from -> to at parameter s in [0, 1] (measured from `from`).
dvec3 faceCanonicalEdgePoint(dvec4 from, dvec4 to, double s) {
  if (s == 0.0lf) return from.xyz;
  if (s == 1.0lf) return to.xyz;
  dvec4 a = from;
  dvec4 b = to;
  precise double t = s;
  if (from.w > to.w) {
    a = to;
    b = from;
    t = 1.0lf - s;
  }
  precise dvec3 d = b.xyz - a.xyz;
  precise dvec3 p = a.xyz + t * d;
  return p;
}

dvec3 faceFlatPoint(FaceCorners f, double u, double v) {
  if (v == 0.0lf) return faceCanonicalEdgePoint(f.corner[0], f.corner[1], u);
  if (u == 1.0lf) return faceCanonicalEdgePoint(f.corner[1], f.corner[2], v);
  if (v == 1.0lf) return faceCanonicalEdgePoint(f.corner[2], f.corner[3], 1.0lf - u);
  if (u == 0.0lf) return faceCanonicalEdgePoint(f.corner[3], f.corner[0], 1.0lf - v);
  precise dvec3 e1 = f.corner[1].xyz - f.corner[0].xyz;
  precise dvec3 e3 = f.corner[3].xyz - f.corner[0].xyz;
  precise dvec3 p = (f.corner[0].xyz + u * e1) + v * e3;
  return p;
}

// The face's frame (= RhombusFaceMapping::faceFrame): rows east (corner 0 to 1), north, up (outward normal).
dmat3 faceFrame(FaceCorners f) {
  dvec3 e1 = f.corner[1].xyz - f.corner[0].xyz, e3 = f.corner[3].xyz - f.corner[0].xyz;
  dvec3 up = normalize(cross(e1, e3)), east = normalize(e1);
  return transpose(dmat3(east, cross(up, east), up));
}

dvec3 faceUnitPoint(FaceCorners f, double u, double v) {
  precise dvec3 p = faceFlatPoint(f, u, v);
  precise double lengthSquared = (p.x * p.x + p.y * p.y) + p.z * p.z;
  precise double inverseLength = 1.0lf / sqrt(lengthSquared);
  precise dvec3 q = p * inverseLength;
  return q;
}

#endif  // GLOBE_FACE_MAPPING_GLSL
