#include "planet/core/data_directory.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace globe {

std::string dataDirectory() {
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path prefix = error ? std::filesystem::path(".") : program.parent_path().parent_path();
  return (prefix / "share" / "globe").string();
}

std::string dataDirectory(const char* environmentVariable, const std::string& subdirectory) {
  const char* value = std::getenv(environmentVariable);
  if (value != nullptr && *value != '\0') return value;
  return dataDirectory() + "/" + subdirectory;
}

std::string userCacheDirectory(const char* environmentVariable, const std::string& name) {
  for (const char* variable : {environmentVariable, "XDG_CACHE_HOME", "HOME"}) {
    const char* value = std::getenv(variable);
    if (value == nullptr || *value == '\0') continue;
    if (variable == environmentVariable) return value;
    return std::string(value) + (variable[0] == 'X' ? "/globe/" : "/.cache/globe/") + name;
  }
  std::error_code error;
  return (std::filesystem::temp_directory_path(error) / ("globe-" + name)).string();
}

}  // namespace globe
