// Body of the terrain vertex stage (terrain.vert; terrain_reprojected.vert defines
// GLOBE_TERRAIN_REPROJECT first). One instance per selected node, vertices pulled from the node's
// payload slot (include/terrain_vertex.glsl does the work, shared with the readback test kernel).
// The shaded colour and its light are the fragment stage's, from the payload's normal map
// (terrain_fragment.glsl, docs/rendering.md "Normal maps"); here only the debug views' colour per
// level, and where the fragment is in the node's normal map.
#include "terrain_vertex.glsl"
#include "display_encoding.glsl"
#include "terrain_level_colour.glsl"

layout(push_constant) uniform Push {
  TerrainDrawPush draw;
} push;

layout(location = 0) out vec3 outColour;  // debug views: the level's colour, display-encoded (display_encoding.h)
layout(location = 1) out float outHole;
// For the water shader (terrain_water.frag; other fragment shaders do not read them, and linking
// drops them): depth of the sea above the ground (m, < 0 on land) and the camera-relative position.
layout(location = 2) out float outSeaDepth;
layout(location = 3) out vec3 outRelative;
// The normal map (terrain_vertex.glsl's TerrainVertex.mapUv, mapBase, mapBlend).
layout(location = 4) out vec2 outMapUv;
layout(location = 5) flat out uint outMapBase;
layout(location = 6) out float outMapBlend;

void main() {
  TerrainVertex v = terrainVertex(uint(gl_VertexIndex), uint(gl_InstanceIndex), push.draw.drawnCells);
  gl_Position = v.clip;
  outColour = encodeDisplay(terrainLevelColour(v.level), 1.0).rgb;  // unlit
  outHole = v.hole;
  outSeaDepth = frame.waterShallow.w - v.elevation;
  outRelative = v.relative;
  outMapUv = v.mapUv;
  outMapBase = v.mapBase;
  outMapBlend = v.mapBlend;
}
