#pragma once
// The two small files every shard of a bake writes identically (atomically, so concurrent shards
// only ever replace them with the same bytes): bake.json, what the bake covers, checked before a
// resume so that tiles of another planet or format are never mixed in; and, for quantized mesh,
// layer.json, the tileset description Cesium clients read (TileJSON 2.1 with availability).
#include "planet/model/elevation_model.h"
#include "planet/tiling/bake_plan.h"

#include <string>
#include <vector>

namespace globe {

struct BakeDescription {
  BakeFormat format = BakeFormat::QuantizedMesh;
  LevelRange levels;
  GeoRect region;
  std::string planet_name;
  double radius_m = 0.0;         // the sphere's radius, or the ellipsoid's equatorial radius
  double flattening = 0.0;       // 0: a sphere; else layer.json says "globe_flattening" too
  std::uint64_t model_hash = 0;  // of the packed elevation parameters and the sources: the model, not its file
};

// The packed parameters' bytes, then every source's description (its path and keys; not the
// raster's bytes): without sources, the parameters' hash alone.
std::uint64_t elevationModelHash(const gpu::ElevationParams& params, const std::vector<ElevationSource>& sources = {});

std::string bakeJson(const BakeDescription& bake);
std::string layerJson(const BakeDescription& bake, const BakePlan& plan);

}  // namespace globe
