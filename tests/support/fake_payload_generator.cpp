#include "tests/support/fake_payload_generator.h"

#include "planet/lod/lod_ranges.h"

#include <algorithm>

namespace globe {

FakePayloadGenerator::FakePayloadGenerator(size_t slotBytes, double radius_m, RadiusRange planet)
    : slotBytes_(slotBytes), radius_m_(radius_m), planet_(planet) {
  running_.reserve(256);
}

void FakePayloadGenerator::generate(std::span<const GenerationJob> jobs) {
  for (const GenerationJob& job : jobs) {
    if (onGenerate) onGenerate(job);
    uint64_t latency = 1 + (job.node.key() * 0x9e3779b97f4a7c15ull >> 62) % 3;  // 1..3 frames
    running_.push_back({job, frame_ + latency});
    ++generatedTotal_;
  }
}

void FakePayloadGenerator::collect(std::vector<GenerationResult>& finished) {
  for (size_t k = 0; k < running_.size();) {
    if (running_[k].readyFrame <= frame_) {
      const NodeId& node = running_[k].job.node;
      double relief = 0.5 * nominalNodeWidth(node.level, radius_m_);
      RadiusRange r{std::max(planet_.min_m, radius_m_ - relief), std::min(planet_.max_m, radius_m_ + relief)};
      const bool failed = failJob && failJob(running_[k].job);
      finished.push_back({node, running_[k].job.slot, failed ? RadiusRange{} : r, failed});
      running_[k] = running_.back();
      running_.pop_back();
    } else {
      ++k;
    }
  }
}

}  // namespace globe
