#include "engine/vk/submit_faults.h"

#include "planet/core/fault_injection.h"

namespace globe::vk {

VkResult injectedSubmitFault(SubmitSite site) {
  // Every submit counts towards a device loss; generation submits also towards their own failure.
  if (injectFault("device-lost")) return VK_ERROR_DEVICE_LOST;
  if (site == SubmitSite::kGeneration && injectFault("generation")) return VK_ERROR_OUT_OF_DEVICE_MEMORY;
  return VK_SUCCESS;
}

}  // namespace globe::vk
