#pragma once
// What one frame cost and what it did: filled by the terrain (selection, streaming, drawing) and the
// frame loop, shown by the viewer's overlay and written by the benchmark and `globe trade`. Plain
// data; zero means "not measured / nothing happened".
#include <cstdint>

namespace globe {

struct FrameStats {
  double frame_ms = 0;   // wall time since the previous frame (milliseconds)
  double select_ms = 0;  // CPU time of LOD selection (milliseconds)
  double gpu_ms = 0;     // GPU time of the frame's work (milliseconds)
  // gpu_ms split by pass (milliseconds; zero where not measured, e.g. the viewer).
  double gpu_terrain_ms = 0;     // the node grids, full and partial
  double gpu_skirts_ms = 0;      // the skirt strips at level changes
  double gpu_sky_ms = 0;         // the sky behind the terrain
  double gpu_shadows_ms = 0;     // the shadow maps' depth passes (engine/render/terrain_shadows.h)
  double gpu_generation_ms = 0;  // payload generation batches collected this frame (own submits)
  uint32_t nodes_selected = 0;   // quadtree nodes drawn
  // Of those, drawn at half resolution (their parent's LOD): children of a refined node that lie
  // beyond their own level's range. Not a payload still generating (the parent is drawn then).
  uint32_t nodes_partial = 0;
  uint64_t triangles = 0;       // triangles submitted
  uint32_t draw_calls = 0;      // draw commands recorded
  uint32_t gen_dispatched = 0;  // payload generation jobs dispatched this frame
  uint32_t gen_in_flight = 0;   // generation jobs on the GPU, not yet complete
  uint32_t gen_completed = 0;   // generation jobs that completed this frame
  uint32_t evicted = 0;         // payloads evicted this frame
  double resident_mib = 0;      // payload memory resident on the GPU (MiB)
  uint32_t queue_length = 0;    // generation requests waiting
  bool converged = false;       // every node the view wants is drawn at its level (Terrain::converged)
  // Normal/colour maps (0 without): the most screen pixels one drawn texel covers (an upper bound,
  // lambda * texel width / distance, planet/imagery/imagery_selection.h), the largest and the 95th
  // percentile over the drawn map cells; and with imagery LOD its tiles drawn this frame.
  double texel_magnification_px = 0;
  double texel_magnification_p95_px = 0;
  uint32_t imagery_tiles = 0;
};

}  // namespace globe
