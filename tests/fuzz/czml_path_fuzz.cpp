// Fuzz target: CZML documents (planet/paths/czml_path.h). Any input gives a path or one error; an
// accepted path, written as a .path file, reads again.
#include "planet/paths/camera_path_file.h"
#include "planet/paths/czml_path.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const globe::Result<globe::CameraPath> path = globe::parseCzmlPath(text, "fuzz.czml");
  if (!path.ok()) return 0;
  if (!globe::parseCameraPath(globe::formatCameraPath(path.value()), "again.path").ok()) std::abort();
  return 0;
}
