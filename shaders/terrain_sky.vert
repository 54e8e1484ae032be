#version 450
// The sky's full-screen triangle (shaders/terrain_sky.frag). The view ray and its component along
// the local vertical are affine in NDC, so they are computed here, per vertex, and interpolated
// exactly (w = 1): the fragment shader is left with one normalisation.
layout(location = 0) out vec3 outRay;  // unnormalised view ray, camera axes scaled by the fov
layout(location = 1) out float outUp;  // dot(outRay, local vertical)

layout(push_constant) uniform Push {
  vec4 right;    // xyz: unit right, w: tan(horizontal fov / 2)
  vec4 up;       // xyz: unit up, w: tan(vertical fov / 2)
  vec4 forward;  // xyz: unit view direction
  vec4 zenith;   // rgb: sky colour straight up; w: atmosphere factor (1 at the ground, 0 in space)
  vec4 horizon;  // rgb: sky colour at the horizon
  vec4 local;    // xyz: local vertical at the camera (unit)
} push;

void main() {
  vec2 ndc = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
  outRay = push.forward.xyz + ndc.x * push.right.w * push.right.xyz - ndc.y * push.up.w * push.up.xyz;
  outUp = dot(outRay, push.local.xyz);
  gl_Position = vec4(ndc, 0.0, 1.0);
}
