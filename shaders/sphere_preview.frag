#version 450
#extension GL_GOOGLE_include_directive : require
#include "include/display_encoding.glsl"
// The planet's reference sphere, ray-cast per pixel in double precision and lit by the sun:
// what `globe render --preview sphere` draws, and a quick check of cameras and depth.
layout(location = 0) in vec2 inNdc;
layout(location = 0) out vec4 outColour;

layout(push_constant) uniform Push {
  dvec4 cameraAndRadius;  // xyz: camera relative to the planet centre (m), w: sphere radius (m)
  vec4 right;             // xyz: unit right, w: tan(horizontal fov / 2)
  vec4 up;                // xyz: unit up, w: tan(vertical fov / 2)
  vec4 forward;           // xyz: unit view direction, w: near plane (m)
  vec4 sun;               // xyz: unit direction towards the sun
} push;

void main() {
  vec3 dir = normalize(push.forward.xyz + inNdc.x * push.right.w * push.right.xyz -
                       inNdc.y * push.up.w * push.up.xyz);
  dvec3 o = push.cameraAndRadius.xyz;
  dvec3 d = dvec3(dir);
  double radius = push.cameraAndRadius.w;
  double len = length(o);
  precise double b = dot(o, d);
  precise double c = (len - radius) * (len + radius);  // |o|^2 - R^2 without cancellation
  precise double disc = b * b - c;
  if (disc < 0.0 || (c > 0.0 && b > 0.0)) {
    outColour = vec4(0.0, 0.0, 0.0, 1.0);  // space
    gl_FragDepth = 0.0;
    return;
  }
  double t = c > 0.0 ? -b - sqrt(disc) : -b + sqrt(disc);
  vec3 normal = vec3(normalize(o + d * t));
  float lambert = max(dot(normal, push.sun.xyz), 0.0);
  vec3 albedo = mix(vec3(0.05, 0.18, 0.35), vec3(0.25, 0.45, 0.2), 0.5 + 0.5 * normal.z);
  outColour = encodeScene(albedo * (0.04 + 0.96 * lambert), 1.0);
  // Reversed-Z with infinite far: depth = near / view-space distance along the view axis.
  float viewZ = float(t) * dot(dir, push.forward.xyz);
  gl_FragDepth = clamp(push.forward.w / viewZ, 0.0, 1.0);
}
