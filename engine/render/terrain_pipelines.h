#pragma once
// The terrain renderer's pipelines: which vertex and fragment stages (shaders/CMakeLists.txt's
// variants) and which bindings a terrain draw uses, from the planet's and the preset's features.
// Internal to engine/render (TerrainRenderer builds its pipelines from these).
#include "engine/render/terrain_renderer.h"
#include "engine/vk/graphics_pipeline.h"

#include <string>

namespace globe {

// The target's colour format and samples per pixel.
struct TargetFormat {
  VkFormat colour;
  VkSampleCountFlagBits samples;
};

// What a terrain pipeline's shaders compute besides the grid: shading from the payloads' normal
// maps, light and aerial perspective through the atmosphere, the sea, the holes' discard, the land
// cover's detail textures.
struct TerrainShading {
  bool normalMaps = false;
  bool atmosphere = false;
  bool water = false;
  bool holes = false;
  bool cover = false;
  bool imagery = false;  // the maps from the imagery tiles (with normalMaps)
  bool shadows = false;  // the sun's light through the shadow maps (with normalMaps)
  // The albedo from each slot's colour layer (a planet with an overlay, payload_layout.h): a
  // specialization constant of the _maps fragment stages (GLOBE_TERRAIN_SPEC_COLOUR_LAYER).
  bool colourLayer = false;
};

// The surface pipelines' shading (the wireframe's has neither water nor holes nor land cover). The
// land cover's splat where the style splats everywhere, or for `nearCamera` (the pipelines of the
// nodes near the camera when it splats there only, TerrainStyle::coverNear). The colour layer where
// the slots have one and `colourLayer` (the nodes whose overlay varies within their cells).
TerrainShading surfaceShading(const TerrainStyle& style, bool atmosphere, bool water, bool nearCamera = false,
                              bool colourLayer = true);

// Creates the surface pipelines of one colour-layer choice (SurfacePipelines, terrain_renderer.h), the sea's on a
// second thread (pipeline creation is most of the renderer's set-up: docs/benchmark.md, "Cold start").
SurfacePipelines makeSurfacePipelines(vk::Device& device, const TerrainStyle& style, VertexPositions positions,
                                      TargetFormat target, bool atmosphere, bool colourLayer);

// Grids are drawn with back faces culled, except on a planet with kept holes (seen through them).
VkCullModeFlags gridCullMode(const TerrainStyle& style);

// terrain[_atmosphere][_maps[_imagery][_shadows]][_water][_holes][_cover].frag: the variants of shaders/CMakeLists.txt.
std::string terrainFragmentShader(const TerrainShading& s);

// The pipeline of a terrain draw: its stages (terrain[_atmosphere|_reprojected][_cover].vert and the
// fragment variant), bindings, push constants and fixed-function state.
vk::GraphicsPipelineDesc terrainDesc(TargetFormat target, bool wireframe, VkCullModeFlags cull,
                                     VertexPositions positions, const TerrainShading& shading);

// The sky behind the terrain (terrain_sky.vert/.frag): drawn where nothing else was (depth 0), with
// `pushConstantBytes` of push constants; `fromSpace` is its specialization for a camera outside the
// atmosphere.
vk::GraphicsPipelineDesc skyDesc(TargetFormat target, uint32_t pushConstantBytes, bool fromSpace);

}  // namespace globe
