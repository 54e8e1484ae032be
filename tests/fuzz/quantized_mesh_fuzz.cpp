// Fuzz target: quantized-mesh tiles (planet/tiling/quantized_mesh_decoder.h), the bytes a baked
// tileset source reads. Any input decodes or is refused, never a crash or undefined behaviour; a
// decoded tile gives finite heights on a grid.
#include "planet/tiling/quantized_mesh_decoder.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const std::optional<globe::DecodedMesh> mesh = globe::decodeQuantizedMesh(bytes);
  if (!mesh) return 0;
  const double lo = mesh->min_height, hi = mesh->max_height, slack = 1e-6 * (1.0 + hi - lo);
  for (double h : globe::meshHeightsOnGrid(*mesh, 8))
    if (!std::isnan(h) && !(h >= lo - slack && h <= hi + slack)) std::abort();
  return 0;
}
