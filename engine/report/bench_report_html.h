#pragma once
// report.html: the benchmark on one page — run info, summary table, the timeline and the key
// frames — for a person. XHTML-compatible markup (every element closed, text escaped) so a plain
// XML parser can check it.
#include "engine/report/bench_report.h"

#include <span>
#include <string>

namespace globe {

// `timelineSvg` is the <svg> element to inline (benchTimelineSvg). `frames` non-empty.
std::string benchReportHtml(const BenchRunInfo& info, std::span<const BenchFrame> frames,
                            std::span<const BenchKeyFrame> keyFrames, const std::string& timelineSvg);

}  // namespace globe
