#include "engine/report/run_environment.h"

#include <cstdlib>
#include <ctime>
#include <fstream>

namespace globe {

namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

// Mesa's own reading of a boolean variable (util/debug.c): these spellings mean true.
bool mesaTrue(const std::string& value) {
  return value == "1" || value == "true" || value == "yes" || value == "y" || value == "t";
}

}  // namespace

std::string mesaShaderCacheState() {
  for (const char* variable : {"MESA_SHADER_CACHE_DISABLE", "MESA_GLSL_CACHE_DISABLE"}) {
    const std::string value = environment(variable);
    if (mesaTrue(value)) return std::string("disabled (") + variable + "=" + value + ")";
  }
  const std::string dir = environment("MESA_SHADER_CACHE_DIR");
  return dir.empty() ? "enabled" : "enabled (MESA_SHADER_CACHE_DIR=" + dir + ")";
}

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  if (!(in >> one >> five >> fifteen)) return "unknown";
  return one + " " + five + " " + fifteen;
}

std::string utcNowIso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace globe
