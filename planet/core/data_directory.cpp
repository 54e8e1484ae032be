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

}  // namespace globe
