#pragma once
// Fault injection for tests (docs/reliability.md, "Faults"): $GLOBE_FAULT makes chosen calls fail,
// so the paths that handle a failed generation, a lost device or a failing disk run on a healthy
// machine. Unarmed (the normal case) a check is one load of a flag read once from the environment.
//
// GLOBE_FAULT is a comma-separated list of KIND@N (the Nth call at that fault point fails) or
// KIND@N+ (that one and every later one), N >= 1. Kinds:
//   generation    a payload-generation submit fails with VK_ERROR_OUT_OF_DEVICE_MEMORY (engine/vk)
//   device-lost   a queue submit of any kind reports VK_ERROR_DEVICE_LOST; a lost device stays lost,
//                 so every later submit does too (engine/vk)
//   fsync         a checked file write's fsync fails with EIO (planet/core/atomic_file.h)
//   write         a write of the benchmark's row spool fails with ENOSPC (engine/report/bench_frame_spool.h)
// Anything else is an error (std::runtime_error) at the first check.
#include <string_view>

namespace globe {

// Counts a call at fault point `kind` (one of the kinds above) and returns true when it must fail.
bool injectFault(std::string_view kind);

// Reads GLOBE_FAULT again and restarts the counts (tests that change it with setenv).
void resetFaultInjection();

}  // namespace globe
