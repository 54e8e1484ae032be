// Body of the terrain vertex stage (terrain.vert; terrain_reprojected.vert defines
// GLOBE_TERRAIN_REPROJECT first). One instance per selected node, vertices pulled from the node's
// payload slot (include/terrain_vertex.glsl does the work, shared with the readback test kernel).
// The surface colour (ramp by elevation and slope, or the debug colour per level) is computed here,
// per vertex: the fragment shader only lights. Evaluating the ramp per fragment from the storage
// buffer cost ~5x the whole frame on lavapipe; at grid resolution the difference is invisible.
#include "terrain_vertex.glsl"
#define GLOBE_RAMP frame.ramp
#include "terrain_shading.glsl"

layout(push_constant) uniform Push {
  TerrainDrawPush draw;
} push;

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec3 outAlbedo;
layout(location = 2) flat out vec4 outSun;  // xyz: towards the sun, w: ambient
layout(location = 3) out vec3 outRelative;
layout(location = 4) out float outHole;

void main() {
  TerrainVertex v = terrainVertex(uint(gl_VertexIndex), uint(gl_InstanceIndex), push.draw.drawnCells);
  gl_Position = v.clip;
  outNormal = v.normal;
  vec3 n = normalize(v.normal);
  // Both colours, then a select (mix with a bool): an if on the debug view (a uniform value) would
  // make lavapipe compile the shader again at draw time (docs/rendering.md).
  bool debug = frame.options.y != GLOBE_TERRAIN_SHADED;
  vec3 ramp = terrainRampColour(v.elevation, clamp(dot(n, v.up), 0.0, 1.0));
  vec3 level = terrainLevelColour(v.level);
  outAlbedo = mix(ramp, level, bvec3(debug));
  outSun = mix(frame.sun, vec4(0.0, 0.0, 0.0, 1.0), bvec4(debug));  // debug colours are shown unlit
  outRelative = v.relative;
  outHole = v.hole;
}
