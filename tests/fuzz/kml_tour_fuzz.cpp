// Fuzz target: KML tours (planet/paths/kml_tour.h). Any input gives a path or one error, never a
// crash, a hang or undefined behaviour; an accepted tour, exported as KML again (formatKmlTour),
// imports again (`path export` once wrote KML that `path import` refused).
#include "planet/paths/kml_tour.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const globe::Result<globe::CameraPath> path = globe::parseKmlTour(text, "fuzz.kml");
  if (!path.ok()) return 0;
  const std::string again = globe::formatKmlTour(path.value(), "fuzz");
  if (!globe::parseKmlTour(again, "again.kml").ok()) std::abort();
  return 0;
}
