#include "engine/render/frame_pass.h"

namespace globe {

void PassMarks::write(VkCommandBuffer cmd, uint32_t mark) {
  for (; next_ <= mark; ++next_) {
    if (timestamps_.pool != VK_NULL_HANDLE)
      vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps_.pool, timestamps_.firstQuery + next_);
  }
}

}  // namespace globe
