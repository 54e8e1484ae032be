#pragma once
// Fault injection for tests (docs/reliability.md, "Faults"): $GLOBE_FAULT makes chosen queue submits
// fail without submitting, so the paths that handle a failed generation or a lost device run on a
// healthy GPU. Unarmed (the normal case) a check is one load of a flag read once from the environment.
//
// GLOBE_FAULT is a comma-separated list of
//   generation@N    the Nth payload-generation submit fails with VK_ERROR_OUT_OF_DEVICE_MEMORY
//   generation@N+   that one and every later one
//   device-lost@N   the Nth queue submit of any kind reports VK_ERROR_DEVICE_LOST, and so does every
//                   later one (a lost device stays lost)
// with N >= 1. Anything else is an error when the first submit is checked.
#include "engine/vk/vk_check.h"

#include <cstdint>

namespace globe::vk {

enum class SubmitSite : uint8_t { kGeneration, kFrame, kOneShot };

// What the submit at `site` reports instead of submitting, or VK_SUCCESS: submit normally. Counts
// the submit. Throws std::runtime_error on a malformed GLOBE_FAULT.
VkResult injectedSubmitFault(SubmitSite site);

// Reads GLOBE_FAULT again and restarts the counts (tests that change the variable with setenv).
void resetFaultInjection();

}  // namespace globe::vk

// A queue submit the fault seam may fail: like GLOBE_VK_CHECK, but an armed fault at `site` is
// reported as `call`'s result and `call` is not made.
#define GLOBE_VK_SUBMIT(site, call)                                                   \
  do {                                                                                \
    VkResult globe_vk_result_ = ::globe::vk::injectedSubmitFault(site);               \
    if (globe_vk_result_ == VK_SUCCESS) globe_vk_result_ = (call);                    \
    if (globe_vk_result_ < 0) ::globe::vk::throwVulkanError(#call, globe_vk_result_); \
  } while (false)
