// Sampling a slot's surface textures (payload_layout.h) in the terrain's _maps fragment stages: one
// trilinear fetch per texture, the LOD being the weight of the parent's map (the mesh's morph factor):
// mip 0 is the node's map, mip 1 its parent's over the node's quadrant, and both are addressed by the
// same coordinate.
#ifndef GLOBE_SURFACE_TEXTURES_GLSL
#define GLOBE_SURFACE_TEXTURES_GLSL

// The layer coordinate of node (u, v) = `uv` in a map of `mapCells` cells per side, layer `layer`:
// the node's cells start two texels into the layer (the gutter).
vec3 surfaceCoordinate(vec2 uv, uint mapCells, uint layer) {
  vec2 at = clamp(uv, vec2(0.0), vec2(1.0)) * float(mapCells) + 2.0;
  return vec3(at / float(GLOBE_SURFACE_TEXTURE_SIDE(mapCells)), float(layer));
}

// The unit normal, in the node's face frame (east, north, up), of a texel's octahedral code `code`
// (its xy, [0, 1]).
vec3 surfaceNormal(vec2 code) {
  vec2 o = code * 2.0 - 1.0;
  vec3 f = vec3(o, 1.0 - abs(o.x) - abs(o.y));
  float fold = max(-f.z, 0.0);
  f.xy += mix(vec2(fold), vec2(-fold), greaterThanEqual(f.xy, vec2(0.0)));
  return normalize(f);
}

#endif  // GLOBE_SURFACE_TEXTURES_GLSL
