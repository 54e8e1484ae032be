#pragma once
// A CPU stand-in for the GPU payload generator: each job finishes a fixed number of frames after it
// was started (1 to 3, from a hash of the node, like the source's "one to three frames"). The radius
// range it reports imitates real terrain: relief shrinks with the node, about half its width at
// most, within the planet's range. Lets whole flights run in CPU tests and benchmarks.
#include "planet/streaming/payload_generator.h"

#include <functional>
#include <string>
#include <vector>

namespace globe {

class FakePayloadGenerator final : public PayloadGenerator {
 public:
  // `slotBytes`: pretend size of one payload; `radius_m`: planet radius; `planet`: the planet's
  // whole radius range (metres from the centre), which no payload exceeds.
  FakePayloadGenerator(size_t slotBytes, double radius_m, RadiusRange planet);

  void generate(std::span<const GenerationJob> jobs) override;
  void collect(std::vector<GenerationResult>& finished) override;
  size_t slotBytes() const override { return slotBytes_; }

  // Advances the fake clock by one frame: jobs whose latency has elapsed become collectable.
  void tick() { ++frame_; }
  // Called for every job as it starts (tests check slot reuse against frames in flight).
  std::function<void(const GenerationJob&)> onGenerate;
  // When set and true for a job, the job comes back failed (GenerationResult::failed).
  std::function<bool(const GenerationJob&)> failJob;
  std::string lastFailure() const override { return "injected by the test"; }
  uint64_t generatedTotal() const { return generatedTotal_; }

 private:
  struct Running {
    GenerationJob job;
    uint64_t readyFrame;
  };
  size_t slotBytes_;
  double radius_m_;
  RadiusRange planet_;
  uint64_t frame_ = 0;
  uint64_t generatedTotal_ = 0;
  std::vector<Running> running_;
};

}  // namespace globe
