#pragma once
// The frame-time distribution for the report: a cumulative distribution (CDF) of frame_ms — for
// every frame time on the x axis, the share of frames at or below it — with the 33.3 ms budget, the
// median and p95 marked. Reads "how often is it smooth" at a glance, which the timeline does not.
#include "engine/report/bench_report.h"

#include <span>
#include <string>

namespace globe {

// The <svg> element alone, for inlining. `frames` non-empty with finite frame_ms.
std::string frameTimeCdfSvg(std::span<const BenchFrame> frames);

}  // namespace globe
