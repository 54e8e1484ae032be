#include "engine/report/bench_report_html.h"

#include "engine/report/bench_baseline.h"
#include "engine/report/bench_distribution_svg.h"
#include "engine/report/bench_metrics.h"
#include "engine/report/bench_phases.h"
#include "engine/report/markup_escape.h"

#include <algorithm>

namespace globe {

namespace {

std::string cell(const std::string& text, const char* tag = "td") {
  return std::string("<") + tag + ">" + escapeMarkup(text) + "</" + tag + ">";
}

std::string infoRow(const std::string& name, const std::string& value) {
  return "<tr>" + cell(name, "th") + cell(value.empty() ? "—" : value) + "</tr>\n";
}

// Fewer decimals than the CSV: the table is for reading, the CSV for computing.
std::string display(double value, const BenchMetric& metric, bool isMean) {
  if (metric.kind == MetricKind::Integer) return formatFixed(value, isMean ? 1 : 0);
  return formatFixed(value, std::min(metric.decimals, 2));
}

constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 2em auto; max-width: 1000px; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em 0; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.6em; }
td.n { text-align: right; font-variant-numeric: tabular-nums; }
th { background: #f3f3f3; text-align: left; }
figure { display: inline-block; margin: 0.5em; }
figure img { max-width: 460px; border: 1px solid #ccc; }
code { background: #f3f3f3; padding: 0 0.2em; }
p.env { color: #555; }
)";

std::string numberCell(const std::string& text) { return "<td class=\"n\">" + escapeMarkup(text) + "</td>"; }

// The header: what the figures depend on besides the code, so two reports can be judged alike.
std::string runSection(const BenchRunInfo& info) {
  std::string out = "<p class=\"env\">" +
                    escapeMarkup(info.device + " · " + (info.driver.empty() ? "driver unknown" : info.driver) +
                                 " · shader cache " + (info.shaderCache.empty() ? "unknown" : info.shaderCache) +
                                 " · load " + (info.loadAverageStart.empty() ? "unknown" : info.loadAverageStart) +
                                 " → " + (info.loadAverageEnd.empty() ? "unknown" : info.loadAverageEnd) +
                                 " · commit " + (info.commit.empty() ? "unknown" : info.commit) + " · " +
                                 (info.dateUtc.empty() ? "date unknown" : info.dateUtc)) +
                    "</p>\n";
  out += "<h2>Run</h2>\n<table>\n";
  out += infoRow("planet", info.planetFile);
  out += infoRow("camera path", info.pathFile);
  out += infoRow("mode", info.mode);
  out += infoRow("device", info.device);
  out += infoRow("driver", info.driver);
  out += infoRow("Mesa shader cache", info.shaderCache);
  out += infoRow("load average (1, 5, 15 min) at start", info.loadAverageStart);
  out += infoRow("load average at end", info.loadAverageEnd);
  out += infoRow("commit", info.commit);
  out += infoRow("date (UTC)", info.dateUtc);
  out += infoRow("image size", info.size);
  out += infoRow("node grid", std::to_string(info.gridCells) + " cells per side");
  out += infoRow("shading", info.shading);
  out += infoRow("globe version", info.globeVersion);
  out += "<tr>" + cell("command", "th") + "<td><code>" + escapeMarkup(info.commandLine) + "</code></td></tr>\n";
  return out + "</table>\n";
}

std::string ratioText(double now, double before) { return before != 0 ? formatFixed(now / before, 2) + "×" : "—"; }

std::string metricsTable(std::span<const BenchFrame> frames, const BenchBaseline* baseline) {
  std::string out =
      "<table>\n<tr><th>metric</th><th>unit</th><th>min</th><th>median</th><th>p95</th><th>p99</th>"
      "<th>max</th><th>mean</th>";
  if (baseline) out += "<th>baseline median</th><th>ratio</th><th>baseline p95</th><th>ratio</th>";
  out += "<th>meaning</th></tr>\n";
  for (const BenchMetric& m : benchMetrics()) {
    const MetricSummary s = summarizeMetric(frames, m);
    out += "<tr><th><code>" + escapeMarkup(m.name) + "</code></th>" + cell(m.unit);
    for (double v : {s.min, s.median, s.p95, s.p99, s.max}) out += numberCell(display(v, m, false));
    out += numberCell(display(s.mean, m, true));
    if (baseline) {
      const MetricSummary* b = baseline->metric(m.name);
      if (b) {
        out += numberCell(display(b->median, m, false)) + numberCell(ratioText(s.median, b->median)) +
               numberCell(display(b->p95, m, false)) + numberCell(ratioText(s.p95, b->p95));
      } else {
        out += "<td>—</td><td>—</td><td>—</td><td>—</td>";
      }
    }
    out += cell(m.description) + "</tr>\n";
  }
  return out + "</table>\n";
}

std::string summarySection(std::span<const BenchFrame> frames, const BenchRunInfo& info,
                           const BenchBaseline* baseline) {
  const double duration_s = frames.back().t_s - frames.front().t_s;
  std::string out = "<h2>Summary</h2>\n<table>\n";
  out += infoRow("frames", std::to_string(frames.size()));
  out += infoRow("path time", formatFixed(duration_s, 2) + " s");
  std::string jank = formatFixed(jankMs(frames), 1) + " ms";
  if (baseline)
    jank += " (baseline " + formatFixed(baseline->jank_ms, 1) + " ms, " + ratioText(jankMs(frames), baseline->jank_ms) +
            ")";
  out += infoRow("jank (Σ max(0, frame_ms − 33.3))", jank);
  out += infoRow("frames over 33.3 ms", std::to_string(framesOverBudget(frames)));
  const GenerationLatency& l = info.latency;
  out += infoRow("generation latency, request → resident (frames)",
                 "p50 " + std::to_string(l.p50_frames) + ", p95 " + std::to_string(l.p95_frames) + ", p99 " +
                     std::to_string(l.p99_frames) + " over " + std::to_string(l.requests) + " requests");
  if (baseline) {
    out +=
        infoRow("baseline", baseline->file + " (commit " + (baseline->commit.empty() ? "unknown" : baseline->commit) +
                                ", " + (baseline->dateUtc.empty() ? "date unknown" : baseline->dateUtc) + ")");
  }
  out += "</table>\n" + metricsTable(frames, baseline);
  out +=
      "<p>Percentiles are nearest-rank over all frames: p<var>k</var> is the value at rank ⌈<var>k</var>/100 · "
      "<var>n</var>⌉ of the <var>n</var> sorted values (the median is p50, the lower middle value for even "
      "<var>n</var>). The same numbers, unrounded, are in <a href=\"summary.json\">summary.json</a>; every "
      "frame is in <a href=\"frames.csv\">frames.csv</a>.";
  if (baseline) out += " Ratios are this run ÷ the baseline: above 1 is more (slower, for times).";
  return out + "</p>\n";
}

std::string phasesSection(std::span<const BenchFrame> frames) {
  std::string out =
      "<h2>Phases of the flight</h2>\n<p>Derived from altitude and ground speed (docs/benchmark.md, "
      "\"Phases\").</p>\n<table>\n<tr><th>phase</th><th>t (s)</th><th>frames</th><th>frame_ms median</th>"
      "<th>frame_ms p95</th><th>nodes median</th><th>triangles median</th></tr>\n";
  for (const PhaseSummary& p : summarizePhases(frames)) {
    out += "<tr>" + cell(p.phase.name, "th") + cell(formatFixed(p.tStart_s, 2) + " – " + formatFixed(p.tEnd_s, 2)) +
           numberCell(std::to_string(p.phase.endFrame - p.phase.firstFrame)) +
           numberCell(formatFixed(p.frameMedian_ms, 2)) + numberCell(formatFixed(p.frameP95_ms, 2)) +
           numberCell(formatFixed(p.nodesMedian, 0)) + numberCell(formatFixed(p.trianglesMedian, 0)) + "</tr>\n";
  }
  return out + "</table>\n";
}

// The GPU time split by pass: medians and each pass's share of the summed medians of gpu_ms.
std::string gpuPassSection(std::span<const BenchFrame> frames) {
  std::string out =
      "<h2>GPU time by pass</h2>\n<table>\n<tr><th>pass</th><th>median (ms)</th><th>p95 (ms)</th>"
      "<th>total over the run (ms)</th></tr>\n";
  for (const char* name :
       {"gpu_shadows_ms", "gpu_terrain_ms", "gpu_skirts_ms", "gpu_sky_ms", "gpu_generation_ms", "gpu_ms"}) {
    const BenchMetric& m = benchMetric(name);
    const MetricSummary s = summarizeMetric(frames, m);
    out += "<tr><th><code>" + escapeMarkup(name) + "</code></th>" + numberCell(formatFixed(s.median, 2)) +
           numberCell(formatFixed(s.p95, 2)) + numberCell(formatFixed(s.mean * double(frames.size()), 1)) + "</tr>\n";
  }
  return out +
         "</table>\n<p><code>gpu_ms</code> is the frame's command buffer (terrain, skirts and sky, plus the clear); "
         "generation runs in its own submissions and is not part of it.</p>\n";
}

}  // namespace

std::string benchReportHtml(const BenchRunInfo& info, std::span<const BenchFrame> frames,
                            std::span<const BenchKeyFrame> keyFrames, const std::string& timelineSvg,
                            const BenchBaseline* baseline) {
  const std::string title = "globe bench: " + info.pathFile + " (" + info.mode + ")";
  std::string out;
  out += "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n";
  out += "<meta charset=\"utf-8\"/>\n<title>" + escapeMarkup(title) + "</title>\n";
  out += std::string("<style>") + kStyle + "</style>\n</head>\n<body>\n";
  out += "<h1>" + escapeMarkup(title) + "</h1>\n";
  out += runSection(info);
  out += summarySection(frames, info, baseline);
  out += "<h2>Frame-time distribution</h2>\n<div class=\"distribution\">\n" + frameTimeCdfSvg(frames) + "</div>\n";
  out += phasesSection(frames);
  out += gpuPassSection(frames);

  out += "<h2>Timeline</h2>\n<p><a href=\"timeline.svg\">timeline.svg</a></p>\n";
  out += "<div class=\"timeline\">\n" + timelineSvg + "</div>\n";

  out += "<h2>Key frames</h2>\n";
  if (keyFrames.empty()) out += "<p>None were rendered.</p>\n";
  for (const BenchKeyFrame& k : keyFrames) {
    const std::string caption = "t = " + formatFixed(k.t_s, 2) + " s";
    out += "<figure><a href=\"" + escapeMarkup(percentEncodePath(k.imageFile)) + "\"><img src=\"" +
           escapeMarkup(percentEncodePath(k.imageFile)) + "\" alt=\"" + escapeMarkup("frame at " + caption) +
           "\"/></a><figcaption>" + escapeMarkup(caption + " (" + k.imageFile + ")") + "</figcaption></figure>\n";
  }

  out += R"(<h2>How to read this</h2>
<p>The timeline's panels share the path-time axis. <b>Frame time</b> is what the viewer feels: frames above the
dashed 33.3 ms line miss 30 fps, and jank adds up by how much. <b>select_ms</b> is the CPU's LOD selection and
<b>gpu_ms</b> the GPU's work; a frame time well above both is spent elsewhere (waiting, generation, the
headless read-back). <b>Nodes</b> rise as the camera nears the ground and detail is needed;
<b>nodes_partial</b> are drawn at half resolution (their parent's LOD) because they lie beyond their own
level's range: normal CDLOD, not streaming (a node whose payload is still generating is not drawn; its
parent is). <b>Generation</b> shows jobs dispatched, completed and evicted each frame, and the
jobs in flight and queued: a queue that keeps growing means generation can't keep up with the camera (the
budgeted mode's bottleneck when flying fast and low; the converged mode waits for generation before drawing,
so its timings show the cost of rendering alone). <b>Altitude</b> (log scale) locates the flight's phases.
The <b>distribution</b> answers "how often is it smooth": read the share of frames left of the 33.3 ms line.
Dotted vertical lines mark the key frames below. A panel whose note says "clipped" has a few values (often the
first frame's shader compile) above its axis; the table has the true maximum.</p>
</body>
</html>
)";
  return out;
}

}  // namespace globe
