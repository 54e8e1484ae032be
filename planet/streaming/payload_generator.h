#pragma once
// The interface between the payload pool (planet/, CPU) and whatever fills payload slots: the GPU
// compute generator in engine/, or a fake in CPU tests and benchmarks. Generation is asynchronous:
// jobs start in generate() and come back through collect() one or more frames later.
#include "planet/geometry/node_bounds.h"
#include "planet/geometry/node_id.h"

#include <span>
#include <string>
#include <vector>

namespace globe {

struct GenerationJob {
  NodeId node;
  uint32_t slot = 0;  // payload slot to fill; the pool guarantees no frame in flight reads it
};

struct GenerationResult {
  NodeId node;
  uint32_t slot = 0;
  RadiusRange radius;  // the payload's real min/max surface radius (metres), padded by the generator
  // The job did not produce a payload (its submit failed, or its output was not finite): the slot
  // holds nothing usable; the pool forgets the node, so the view draws its parent and asks again.
  bool failed = false;
  double geometricError_m = 0.0;  // largest vertex move when the mesh morphs to its parent's (metres)
};

class PayloadGenerator {
 public:
  virtual ~PayloadGenerator() = default;
  // Starts generating `jobs` (at most the pool's per-frame budget). Must not block on the GPU.
  virtual void generate(std::span<const GenerationJob> jobs) = 0;
  // Appends the jobs that have finished since the last call. Must not block.
  virtual void collect(std::vector<GenerationResult>& finished) = 0;
  // Bytes of device memory one payload slot takes (positions, normals, ...).
  virtual size_t slotBytes() const = 0;
  // Why the last failed job failed (one line), for the pool's warning; empty if none failed.
  virtual std::string lastFailure() const { return {}; }
};

}  // namespace globe
