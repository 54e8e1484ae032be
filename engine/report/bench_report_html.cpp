#include "engine/report/bench_report_html.h"

#include "engine/report/bench_metrics.h"
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
)";

}  // namespace

std::string benchReportHtml(const BenchRunInfo& info, std::span<const BenchFrame> frames,
                            std::span<const BenchKeyFrame> keyFrames, const std::string& timelineSvg) {
  const double duration_s = frames.back().t_s - frames.front().t_s;
  const std::string title = "globe bench: " + info.pathFile + " (" + info.mode + ")";
  std::string out;
  out += "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n";
  out += "<meta charset=\"utf-8\"/>\n<title>" + escapeMarkup(title) + "</title>\n";
  out += std::string("<style>") + kStyle + "</style>\n</head>\n<body>\n";
  out += "<h1>" + escapeMarkup(title) + "</h1>\n";

  out += "<h2>Run</h2>\n<table>\n";
  out += infoRow("planet", info.planetFile);
  out += infoRow("camera path", info.pathFile);
  out += infoRow("mode", info.mode);
  out += infoRow("device", info.device);
  out += infoRow("image size", info.size);
  out += infoRow("node grid", std::to_string(info.gridCells) + " cells per side");
  out += infoRow("globe version", info.globeVersion);
  out += "<tr>" + cell("command", "th") + "<td><code>" + escapeMarkup(info.commandLine) + "</code></td></tr>\n";
  out += "</table>\n";

  out += "<h2>Summary</h2>\n<table>\n";
  out += infoRow("frames", std::to_string(frames.size()));
  out += infoRow("path time", formatFixed(duration_s, 2) + " s");
  out += infoRow("jank (Σ max(0, frame_ms − 33.3))", formatFixed(jankMs(frames), 1) + " ms");
  out += infoRow("frames over 33.3 ms", std::to_string(framesOverBudget(frames)));
  out +=
      "</table>\n<table>\n<tr><th>metric</th><th>unit</th><th>min</th><th>median</th><th>p95</th><th>p99</th>"
      "<th>max</th><th>mean</th><th>meaning</th></tr>\n";
  for (const BenchMetric& m : benchMetrics()) {
    const MetricSummary s = summarizeMetric(frames, m);
    out += "<tr><th><code>" + escapeMarkup(m.name) + "</code></th>" + cell(m.unit);
    for (double v : {s.min, s.median, s.p95, s.p99, s.max}) out += "<td class=\"n\">" + display(v, m, false) + "</td>";
    out += "<td class=\"n\">" + display(s.mean, m, true) + "</td>" + cell(m.description) + "</tr>\n";
  }
  out += "</table>\n";
  out +=
      "<p>Percentiles are nearest-rank over all frames: p<var>k</var> is the value at rank ⌈<var>k</var>/100 · "
      "<var>n</var>⌉ of the <var>n</var> sorted values (the median is p50, the lower middle value for even "
      "<var>n</var>). The same numbers, unrounded, are in <a href=\"summary.json\">summary.json</a>; every "
      "frame is in <a href=\"frames.csv\">frames.csv</a>.</p>\n";

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
<b>nodes_partial</b> are drawn at half resolution because their payload is still generating, so a tall red
line means visible pops. <b>Generation</b> shows jobs dispatched, completed and evicted each frame, and the
jobs in flight and queued: a queue that keeps growing means generation can't keep up with the camera (the
budgeted mode's bottleneck when flying fast and low; the converged mode waits for generation before drawing,
so its nodes are never partial and its timings show the cost of rendering alone). <b>Altitude</b> (log scale) locates the flight's phases.
Dotted vertical lines mark the key frames below. A panel whose note says "clipped" has a few values (often the
first frame's shader compile) above its axis; the table has the true maximum.</p>
</body>
</html>
)";
  return out;
}

}  // namespace globe
