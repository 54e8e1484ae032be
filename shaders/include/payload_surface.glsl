// The surface word of a payload sample (normal.w, shaders/include/payload_layout.h): albedo and hole
// mask packed as 4 unsigned bytes, written by the payload kernel, read by the terrain vertex stage.
// The word travels as the bits of a float and is only ever bit-cast, never computed with.
// The albedo is stored as its square root: 8 linear bits would band the dark colours (a deep sea
// of 0.005 is one step), a square root gives them 18 steps below 0.005. Mirrored by
// globe::packPayloadSurface (planet/streaming/payload_reference.h).
#ifndef GLOBE_PAYLOAD_SURFACE_GLSL
#define GLOBE_PAYLOAD_SURFACE_GLSL

float packPayloadSurface(vec3 albedo, float hole) {
  return uintBitsToFloat(packUnorm4x8(vec4(sqrt(clamp(albedo, 0.0, 1.0)), hole)));
}

// xyz = linear albedo, w = hole mask.
vec4 unpackPayloadSurface(float word) {
  vec4 c = unpackUnorm4x8(floatBitsToUint(word));
  return vec4(c.rgb * c.rgb, c.a);
}

#endif  // GLOBE_PAYLOAD_SURFACE_GLSL
