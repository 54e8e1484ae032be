#version 450
// Background behind the terrain: a cheap sky gradient by the angle between the view ray and the
// local vertical, fading to black space as the camera climbs through the atmosphere height.
// No depth written (the depth buffer stays at its clear value 0 = infinitely far).
layout(location = 0) in vec2 inNdc;
layout(location = 0) out vec4 outColour;

layout(push_constant) uniform Push {
  vec4 right;    // xyz: unit right, w: tan(horizontal fov / 2)
  vec4 up;       // xyz: unit up, w: tan(vertical fov / 2)
  vec4 forward;  // xyz: unit view direction
  vec4 zenith;   // rgb: sky colour straight up; w: atmosphere factor (1 at the ground, 0 in space)
  vec4 horizon;  // rgb: sky colour at the horizon
  vec4 local;    // xyz: local vertical at the camera (unit)
} push;

void main() {
  vec3 dir = normalize(push.forward.xyz + inNdc.x * push.right.w * push.right.xyz -
                       inNdc.y * push.up.w * push.up.xyz);
  float t = dot(dir, push.local.xyz);
  vec3 sky = mix(push.horizon.rgb, push.zenith.rgb, sqrt(clamp(t, 0.0, 1.0)));
  outColour = vec4(sky * push.zenith.w, 1.0);
}
