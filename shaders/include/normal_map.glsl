// A payload's normal map texels (shaders/include/payload_layout.h): packed by the payload kernel,
// sampled bilinearly per fragment by the terrain fragment stages. Mirrored on the CPU by
// planet/streaming/normal_map_reference.h.
// Texel = uvec2: x = octahedral u (20 bits) | low 12 bits of octahedral v << 20;
//                y = sqrt(albedo) as 3 unorm bytes | high 8 bits of octahedral v << 24.
#ifndef GLOBE_NORMAL_MAP_GLSL
#define GLOBE_NORMAL_MAP_GLSL

#ifdef GLOBE_NORMAL_MAP_PACK
// The octahedral code of a unit normal (in double: the stored value is the double normal rounded
// once, to 2^-20 of the octahedron's half width) and the albedo's square root.
uvec2 packNormalMapTexel(dvec3 n, vec3 albedo) {
  precise double l1 = (abs(n.x) + abs(n.y)) + abs(n.z);
  precise dvec2 o = n.xy / l1;
  dvec2 signs = dvec2(o.x >= 0.0lf ? 1.0lf : -1.0lf, o.y >= 0.0lf ? 1.0lf : -1.0lf);
  if (n.z < 0.0lf) o = (1.0lf - abs(o.yx)) * signs;
  uvec2 q = uvec2(floor((o * 0.5lf + 0.5lf) * 1048575.0lf + 0.5lf));
  uint colour = packUnorm4x8(vec4(sqrt(clamp(albedo, 0.0, 1.0)), 0.0)) & 0xffffffu;
  return uvec2(q.x | (q.y << 20), colour | ((q.y >> 12) << 24));
}
#endif

vec3 normalMapNormal(uvec2 texel) {
  uvec2 q = uvec2(texel.x & 0xfffffu, (texel.x >> 20) | ((texel.y >> 24) << 12));
  vec2 o = vec2(q) * (2.0 / 1048575.0) - 1.0;
  vec3 n = vec3(o, 1.0 - abs(o.x) - abs(o.y));
  float fold = max(-n.z, 0.0);
  n.xy += mix(vec2(fold), vec2(-fold), greaterThanEqual(n.xy, vec2(0.0)));
  return normalize(n);
}

#ifdef GLOBE_NORMAL_MAP_SAMPLE
#ifndef GLOBE_NORMAL_MAP_TEXEL
#define GLOBE_NORMAL_MAP_TEXEL(i) payloadTexels[i]
#endif
// Bilinear sample of one map level whose texels (side x side) start at `base` in
// GLOBE_NORMAL_MAP_TEXEL(i) (payloadTexels[i] unless the includer defines another source), at
// `at` in texel units: the normal (not renormalised) and sqrt(albedo).
void sampleNormalMap(uint base, uint side, vec2 at, out vec3 normal, out vec3 rootAlbedo) {
  vec2 c = clamp(at, vec2(0.0), vec2(float(side - 1u)));
  uvec2 corner = min(uvec2(c), uvec2(side - 2u));
  vec2 f = c - vec2(corner);
  uint i = base + corner.y * side + corner.x;
  uvec2 t00 = GLOBE_NORMAL_MAP_TEXEL(i), t10 = GLOBE_NORMAL_MAP_TEXEL(i + 1u);
  uvec2 t01 = GLOBE_NORMAL_MAP_TEXEL(i + side), t11 = GLOBE_NORMAL_MAP_TEXEL(i + side + 1u);
  normal = mix(mix(normalMapNormal(t00), normalMapNormal(t10), f.x), mix(normalMapNormal(t01), normalMapNormal(t11), f.x),
               f.y);
  rootAlbedo = mix(mix(unpackUnorm4x8(t00.y).rgb, unpackUnorm4x8(t10.y).rgb, f.x),
                   mix(unpackUnorm4x8(t01.y).rgb, unpackUnorm4x8(t11.y).rgb, f.x), f.y);
}
#endif

#endif  // GLOBE_NORMAL_MAP_GLSL
