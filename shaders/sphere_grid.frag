#version 450
#extension GL_GOOGLE_include_directive : require
#include "include/display_encoding.glsl"
// The viewer's debug view over the sphere preview: latitude/longitude lines every 10 degrees
// (equator and prime meridian brighter), ray-cast in double like sphere_preview.frag and blended
// on top (premultiplied alpha). The terrain renderer's LOD colours reuse the same toggle.
layout(location = 0) in vec2 inNdc;
layout(location = 0) out vec4 outColour;

layout(push_constant) uniform Push {
  dvec4 cameraAndRadius;  // xyz: camera relative to the planet centre (m), w: sphere radius (m)
  vec4 right;             // xyz: unit right, w: tan(horizontal fov / 2)
  vec4 up;                // xyz: unit up, w: tan(vertical fov / 2)
  vec4 forward;           // xyz: unit view direction, w: grid spacing (degrees)
} push;

const float kPi = 3.14159265358979;

void main() {
  vec3 dir = normalize(push.forward.xyz + inNdc.x * push.right.w * push.right.xyz -
                       inNdc.y * push.up.w * push.up.xyz);
  dvec3 o = push.cameraAndRadius.xyz;
  dvec3 d = dvec3(dir);
  double radius = push.cameraAndRadius.w;
  double len = length(o);
  precise double b = dot(o, d);
  precise double c = (len - radius) * (len + radius);
  precise double disc = b * b - c;
  if (disc < 0.0 || (c > 0.0 && b > 0.0)) discard;
  double t = c > 0.0 ? -b - sqrt(disc) : -b + sqrt(disc);
  vec3 n = vec3(normalize(o + d * t));
  float lat = degrees(asin(clamp(n.z, -1.0, 1.0)));
  float lon = degrees(atan(n.y, n.x));
  float spacing = push.forward.w;
  // Distance to the nearest line in screen pixels (fwidth), for lines ~1.5 px wide at any zoom.
  vec2 cell = vec2(lat, lon) / spacing;
  vec2 toLine = abs(fract(cell + 0.5) - 0.5) / max(fwidth(cell), vec2(1e-6));
  float line = 1.0 - clamp(min(toLine.x, toLine.y) - 0.75, 0.0, 1.0);
  bool principal = (abs(lat) < spacing * 0.5 && toLine.x < 1.5) || (abs(lon) < spacing * 0.5 && toLine.y < 1.5);
  vec3 colour = principal ? vec3(1.0, 0.35, 0.2) : vec3(0.9, 0.85, 0.4);
  float alpha = line * 0.8;
  if (alpha <= 0.0) discard;
  // Premultiplied in the stored encoding: blending happens on what the target holds.
  outColour = vec4(encodeDisplay(colour, alpha).rgb * alpha, alpha);
}
