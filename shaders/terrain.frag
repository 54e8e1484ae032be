#version 450
// Terrain shading: Lambert light from the sun on the interpolated (morphed) normal times the
// vertex colour (terrain.vert). Reads no buffers: per-fragment cost is what bounds lavapipe.
layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec3 inAlbedo;
layout(location = 2) flat in vec4 inSun;
layout(location = 3) in vec3 inRelative;
layout(location = 0) out vec4 outColour;

void main() {
  vec3 n = normalize(inNormal);
  float light = inSun.w + (1.0 - inSun.w) * max(dot(n, inSun.xyz), 0.0);
  outColour = vec4(inAlbedo * light, 1.0);
}
