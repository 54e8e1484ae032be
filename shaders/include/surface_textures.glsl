// Sampling a slot's surface textures (payload_layout.h) in the terrain's _maps fragment stages: the
// sampler's bilinear filter between texel centres is the map's bilinear interpolation, so a level is
// read with one fetch per texture (no mips: texels sit on the map grid's corners and the coordinates
// never leave the level's own texels).
#ifndef GLOBE_SURFACE_TEXTURES_GLSL
#define GLOBE_SURFACE_TEXTURES_GLSL

// The layer coordinate of node (u, v) = `uv` in level `level` (0: the node's map, 1: its parent's
// over the node's quadrant) of a map with `mapCells` cells per side, in layer `layer`.
vec3 surfaceCoordinate(vec2 uv, uint level, uint mapCells, uint layer) {
  float cells = float(mapCells >> level);
  vec2 at = clamp(uv, vec2(0.0), vec2(1.0)) * cells + 0.5;
  at.x += level == 0u ? 0.0 : float(mapCells + 1u);
  vec2 size = vec2(float(GLOBE_SURFACE_TEXTURE_WIDTH(mapCells)), float(GLOBE_SURFACE_TEXTURE_HEIGHT(mapCells)));
  return vec3(at / size, float(layer));
}

#endif  // GLOBE_SURFACE_TEXTURES_GLSL
