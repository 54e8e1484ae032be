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

#endif  // GLOBE_SURFACE_TEXTURES_GLSL
