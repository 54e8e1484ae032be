#pragma once
// The benchmark timeline (timeline.svg): stacked panels over path time sharing one x axis, after
// the primary source's figure 27 — frame and selection time, nodes, generation, memory, altitude.
// Hand-written SVG with no dependencies.
#include "engine/report/bench_report.h"

#include <cstddef>
#include <span>
#include <string>

namespace globe {

// Above this many frames each series is drawn through the minimum and maximum of consecutive
// buckets (kTimelineMaxPoints / 2 of them) instead of every frame: the file stays small and
// spikes stay visible.
inline constexpr std::size_t kTimelineMaxPoints = 5000;

// The <svg> element alone (no XML declaration), so the report can inline it. `frames` non-empty,
// in increasing time, finite.
std::string benchTimelineSvg(const BenchRunInfo& info, std::span<const BenchFrame> frames,
                             std::span<const BenchKeyFrame> keyFrames);

}  // namespace globe
