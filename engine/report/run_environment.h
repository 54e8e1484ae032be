#pragma once
// What besides the code affects a benchmark's figures, read from the process's environment: the
// Mesa shader cache settings, the machine's load average, the wall-clock date. No Vulkan here
// (the caller adds the device and driver). docs/benchmark.md, "summary.json".
#include <string>

namespace globe {

// "enabled" (Mesa's default cache), "enabled (MESA_SHADER_CACHE_DIR=...)" or
// "disabled (MESA_SHADER_CACHE_DISABLE=true)" (likewise the older MESA_GLSL_CACHE_DISABLE). A cold
// cache recompiles every shader: first frames cost hundreds of milliseconds more.
std::string mesaShaderCacheState();

// The 1, 5 and 15 minute load averages from /proc/loadavg ("1.09 1.90 1.24"), or "unknown".
// Other processes share the CPU with lavapipe, so a loaded machine slows every frame.
std::string loadAverage();

// Now, UTC, ISO 8601 to the second: "2026-12-01T16:36:56Z".
std::string utcNowIso8601();

}  // namespace globe
