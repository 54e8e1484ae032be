// Fuzz target: camera path files (planet/paths/camera_path_file.h). An accepted path must survive
// formatting and re-parsing (the writer's output is always readable).
#include "planet/paths/camera_path_file.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const globe::Result<globe::CameraPath> path = globe::parseCameraPath(text, "fuzz.path");
  if (!path.ok()) return 0;
  const std::string again = globe::formatCameraPath(path.value());
  if (!globe::parseCameraPath(again, "again.path").ok()) std::abort();
  return 0;
}
