// Fuzz target: a planet file's [[sources]] entries (planet/sources/source_toml.h). The input follows
// a fixed valid planet, read as if it lay in assets/planets/ so the shipped DEM mosaics' relative
// paths resolve (GDAL opens them: VRTs, rasters, baked tilesets). Any input gives a planet or
// errors, never a crash, a hang or undefined behaviour, and both entry points agree on validity.
#include "planet/gdal/gdal_readers.h"
#include "planet/model/planet_file.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {
constexpr const char* kPlanet =
    "name = \"fuzz\"\nradius_m = 6371000.0\n[[layers]]\nname = \"base\"\noctaves = 4\nwavelength_m = 1e6\n"
    "amplitude_m = 1000\n";
const std::string kFile = std::string(GLOBE_SOURCE_DIR) + "/assets/planets/fuzz.toml";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  globe::installGdalReaders();  // as the globe program reads planet files (once; later calls do nothing)
  const std::string text = kPlanet + std::string(reinterpret_cast<const char*>(data), size);
  const globe::Result<globe::PlanetDescription> planet = globe::parsePlanetToml(text, kFile);
  const globe::PlanetFileCheck check = globe::checkPlanetToml(text, kFile);
  if (planet.ok() != check.errors.empty()) std::abort();
  return 0;
}
