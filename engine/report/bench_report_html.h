#pragma once
// report.html: the benchmark on one page — what the figures depend on (device, driver, shader
// cache, load, commit, date), the summary table, the frame-time distribution, the flight's phases,
// the GPU time by pass, the timeline and the key frames — for a person. XHTML-compatible markup (every element closed,
// text escaped) so a plain XML parser can check it.
#include "engine/report/bench_report.h"

#include <span>
#include <string>

namespace globe {

struct BenchBaseline;

// `timelineSvg` is the <svg> element to inline (benchTimelineSvg). `frames` non-empty. With a
// baseline, the summary table gets its medians and p95s and the ratios beside this run's.
std::string benchReportHtml(const BenchRunInfo& info, std::span<const BenchFrame> frames,
                            std::span<const BenchKeyFrame> keyFrames, const std::string& timelineSvg,
                            const BenchBaseline* baseline = nullptr);

}  // namespace globe
