// Fuzz target: TOML planet files (planet/model/planet_file.h). Any input must give a description
// or errors, never a crash, a hang or undefined behaviour; an accepted description must check clean.
#include "planet/gdal/gdal_readers.h"
#include "planet/model/planet_file.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  globe::installGdalReaders();  // as the globe program reads planet files (once; later calls do nothing)
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const globe::Result<globe::PlanetDescription> planet = globe::parsePlanetToml(text, "fuzz.toml");
  const globe::PlanetFileCheck check = globe::checkPlanetToml(text, "fuzz.toml");
  // The two entry points agree on whether the file is valid.
  if (planet.ok() != check.errors.empty()) std::abort();
  return 0;
}
