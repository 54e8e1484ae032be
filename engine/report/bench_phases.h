#pragma once
// The flight's phases (approach, hover, low pass, climb, exit), derived from the camera's altitude
// and ground speed, so the report can say which part of a flight is slow. Path files carry no
// phase names; the rules are in docs/benchmark.md ("Phases").
#include "engine/report/bench_report.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace globe {

struct FlightPhase {
  const char* name;        // "approach", "hover", "low pass", "climb" or "exit"
  std::size_t firstFrame;  // index into the frames
  std::size_t endFrame;    // one past the last frame
};

// Consecutive segments covering every frame in order (one segment for very short runs).
std::vector<FlightPhase> flightPhases(std::span<const BenchFrame> frames);

// Statistics of one phase for the report and summary.json.
struct PhaseSummary {
  FlightPhase phase;
  double tStart_s = 0, tEnd_s = 0;
  double frameMedian_ms = 0, frameP95_ms = 0;
  double nodesMedian = 0;
  double trianglesMedian = 0;
};
std::vector<PhaseSummary> summarizePhases(std::span<const BenchFrame> frames);

}  // namespace globe
