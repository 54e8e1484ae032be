// The sun's share reaching a terrain fragment through the relief, from the cascaded shadow maps
// (engine/render/shadow_cascades.h, terrain_shadows.h): the finest cascade whose box holds the
// fragment, its depth compared with the map's (the sampler's 2 x 2 filter softens the edge); 1
// outside every box, and fading to 1 over the last one's rim so that no line marks where shadows end.
// Needs the frame constants (TerrainFrame) declared first.
#ifndef GLOBE_TERRAIN_SHADOWS_GLSL
#define GLOBE_TERRAIN_SHADOWS_GLSL
#extension GL_EXT_control_flow_attributes : require

layout(set = 0, binding = GLOBE_TERRAIN_SHADOW_BINDING) uniform sampler2DArrayShadow shadowMaps;

// `cosSun`: the cosine between the surface's normal and the sunlight. The depth bias grows with the
// angle's tangent: a slope lit at a grazing angle changes depth fast across a texel and would shade
// itself in texel-sized blocks.
float sunVisibility(vec3 relative, float cosSun) {
  float c = max(cosSun, 0.05);
  float slope = min(sqrt(1.0 - c * c) / c, 8.0);
  uint count = uint(frame.shadow.x);
  vec4 at = vec4(0.0);
  float edge = 2.0;  // the chosen box's |x|, |y| max: > 1 when no box holds the fragment
  bool last = false;
  // Coarsest first: a finer box that holds the fragment replaces it. Selects, no branches.
  [[unroll]] for (int c = GLOBE_SHADOW_CASCADES - 1; c >= 0; --c) {
    vec4 clip = frame.shadowFromCamera[c] * vec4(relative, 1.0);
    float e = max(abs(clip.x), abs(clip.y));
    bool inside = uint(c) < count && e < 1.0 && clip.z < 1.0;
    at = inside ? vec4(clip.xy * 0.5 + 0.5, float(c), clip.z - frame.shadowBias[c] * (1.0 + slope)) : at;
    last = inside ? uint(c) + 1u == count : last;
    edge = inside ? e : edge;
  }
  float lit = texture(shadowMaps, at);
  float fade = last ? smoothstep(frame.shadow.y, 1.0, edge) : (edge > 1.0 ? 1.0 : 0.0);
  return mix(lit, 1.0, fade);
}
#endif
