#include "engine/render/terrain_pipelines.h"

#include "shaders/include/terrain_layout.h"

#include <cassert>
#include <future>
#include <string_view>

namespace globe {

TerrainShading surfaceShading(const TerrainStyle& style, bool atmosphere, bool water, bool nearCamera,
                              bool colourLayer) {
  const bool maps = style.normalMapScale > 0 || style.imagery;
  return {maps,
          atmosphere,
          water,
          style.holes,
          style.coverEverywhere() || (nearCamera && style.coverNear()),
          style.imagery,
          maps && style.shadows,
          colourLayer && style.surfaceLayersPerSlot == 2 && !style.imagery};
}

VkCullModeFlags gridCullMode(const TerrainStyle& style) {
  return style.holes ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
}

std::string terrainFragmentShader(const TerrainShading& s) {
  return std::string("terrain") + (s.atmosphere ? "_atmosphere" : "") + (s.normalMaps ? "_maps" : "") +
         (s.normalMaps && s.imagery ? "_imagery" : "") + (s.normalMaps && s.shadows ? "_shadows" : "") +
         (s.water ? "_water" : "") + (s.holes ? "_holes" : "") + (s.cover ? "_cover" : "") + ".frag";
}

vk::GraphicsPipelineDesc terrainDesc(TargetFormat target, bool wireframe, VkCullModeFlags cull,
                                     VertexPositions positions, const TerrainShading& shading) {
  vk::GraphicsPipelineDesc d;
  const bool reprojected = positions == VertexPositions::kReprojected;
  const bool atmosphere = shading.atmosphere;
  d.vertexShader = reprojected ? "terrain_reprojected.vert" : atmosphere ? "terrain_atmosphere.vert" : "terrain.vert";
  d.fragmentShader = terrainFragmentShader(shading);
  // 0: instances, 1: payloads, 2: frame constants (uniform); reprojected: 3 nodes' (u, v), 4 faces;
  // atmosphere: 3 its parameters (uniform), 4-6 its tables, 7 the frame's camera (uniform), 8 its
  // aerial perspective table (AtmosphereView).
  d.storageBuffers = reprojected ? 5 : atmosphere ? 9 : 3;
  // Imagery: 3 or 9 the cell tables (GLOBE_TERRAIN_IMAGERY_BINDING).
  assert(!shading.imagery || !reprojected);
  if (shading.imagery && shading.normalMaps) d.storageBuffers += 1;
  d.uniformMask = atmosphere ? (1u << 2) | (1u << 3) | (1u << 7) : 1u << 2;
  d.pushConstantBytes = sizeof(gpu::TerrainDrawPush);
  d.colourFormat = target.colour;
  d.samples = target.samples;
  d.wireframe = wireframe;
  d.cull = cull;
  if (shading.cover) {
    d.sampledImageBindings.push_back(GLOBE_TERRAIN_DETAIL_BINDING);
    d.vertexShader.insert(d.vertexShader.size() - std::string_view(".vert").size(), "_cover");
  }
  // The surface texture: the drawn page's, or the imagery tiles' pages'.
  const uint32_t surfaceBindings = !shading.normalMaps ? 0 : shading.imagery ? GLOBE_IMAGERY_TILE_PAGES : 1;
  for (uint32_t b = 0; b < surfaceBindings; ++b) d.sampledImageBindings.push_back(GLOBE_TERRAIN_SURFACE_BINDING + b);
  if (shading.normalMaps && shading.shadows) d.sampledImageBindings.push_back(GLOBE_TERRAIN_SHADOW_BINDING);
  // A constant, not a uniform branch: lavapipe ran the colour layer's fetch for every fragment of a
  // planet without one behind a frame flag (+3 ms on the flyover, docs/imagery.md).
  static_assert(GLOBE_TERRAIN_SPEC_COLOUR_LAYER == 0);
  if (shading.normalMaps) d.fragmentSpecialization = {shading.colourLayer ? 1u : 0u};
  return d;
}

SurfacePipelines makeSurfacePipelines(vk::Device& device, const TerrainStyle& style, VertexPositions positions,
                                      TargetFormat target, bool atmosphere, bool colourLayer) {
  auto make = [&](VkCullModeFlags cull, bool water, bool nearCamera) {
    return std::make_unique<vk::GraphicsPipeline>(
        device,
        terrainDesc(target, false, cull, positions, surfaceShading(style, atmosphere, water, nearCamera, colourLayer)));
  };
  // The surface is seen from above only (the camera never goes under it): its back faces are always
  // hidden behind front faces, and culling them halves the rasteriser's work. Skirts fill gaps seen
  // from either side. A planet with kept holes draws both faces (gridCullMode), so that the surface
  // and the hole's rim are seen from below through the hole too.
  SurfacePipelines p;
  std::future<void> sea;
  if (style.water.enabled)
    sea = std::async(std::launch::async, [&] {
      p.water = make(gridCullMode(style), true, false);
      p.waterSkirts = make(VK_CULL_MODE_NONE, true, false);
      if (style.coverNear()) p.waterDetail = make(gridCullMode(style), true, true);
    });
  p.solid = make(gridCullMode(style), false, false);
  p.skirts = make(VK_CULL_MODE_NONE, false, false);
  if (style.coverNear()) p.solidDetail = make(gridCullMode(style), false, true);
  if (sea.valid()) sea.get();  // rethrows what creation threw
  return p;
}

vk::GraphicsPipelineDesc skyDesc(TargetFormat target, uint32_t pushConstantBytes, bool fromSpace) {
  vk::GraphicsPipelineDesc d;
  d.vertexShader = "terrain_sky.vert";
  d.fragmentShader = "terrain_sky.frag";
  d.storageBuffers = 4;  // the atmosphere's parameters (uniform) and tables
  d.uniformMask = 1u << 0;
  d.pushConstantBytes = pushConstantBytes;
  d.colourFormat = target.colour;
  d.samples = target.samples;
  d.depthTest = true;  // GREATER_OR_EQUAL against depth 0: passes only where nothing was drawn
  d.depthWrite = false;
  // constant_id 0 of terrain_sky.frag: 1 seen from outside the atmosphere, where the pixels near
  // the shell evaluate the sky themselves. From inside, lavapipe ran that evaluation's code for
  // every sky pixel although its branch was never taken (+8 ms a frame on the flyover).
  d.fragmentSpecialization = {fromSpace ? 1u : 0u};
  if (fromSpace) d.vertexSpecialization = {1u};
  return d;
}

}  // namespace globe
