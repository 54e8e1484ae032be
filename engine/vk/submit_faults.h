#pragma once
// The queue submits' fault points (planet/core/fault_injection.h: $GLOBE_FAULT's `generation` and
// `device-lost`): a submit the seam fails is not made, and reports the injected result instead.
#include "engine/vk/vk_check.h"

#include <cstdint>

namespace globe::vk {

enum class SubmitSite : uint8_t { kGeneration, kFrame, kOneShot };

// What the submit at `site` reports instead of submitting, or VK_SUCCESS: submit normally. Counts
// the submit. Throws std::runtime_error on a malformed GLOBE_FAULT.
VkResult injectedSubmitFault(SubmitSite site);

}  // namespace globe::vk

// A queue submit the fault seam may fail: like GLOBE_VK_CHECK, but an armed fault at `site` is
// reported as `call`'s result and `call` is not made.
#define GLOBE_VK_SUBMIT(site, call)                                                   \
  do {                                                                                \
    VkResult globe_vk_result_ = ::globe::vk::injectedSubmitFault(site);               \
    if (globe_vk_result_ == VK_SUCCESS) globe_vk_result_ = (call);                    \
    if (globe_vk_result_ < 0) ::globe::vk::throwVulkanError(#call, globe_vk_result_); \
  } while (false)
