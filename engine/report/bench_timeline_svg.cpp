#include "engine/report/bench_timeline_svg.h"

#include "engine/report/bench_metrics.h"
#include "engine/report/markup_escape.h"
#include "engine/report/svg_axis.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace globe {

namespace {

// Layout in SVG user units (pixels at 100 %).
constexpr double kWidth = 960;
constexpr double kLeft = 72;  // room for y tick labels
constexpr double kRight = 16;
constexpr double kPlotWidth = kWidth - kLeft - kRight;
constexpr double kTitleHeight = 40;
constexpr double kPanelHeader = 24;  // panel title and legend
constexpr double kPlotHeight = 96;
constexpr double kPanelGap = 10;
constexpr double kAxisHeight = 40;      // x tick labels and the axis title under the last panel
constexpr double kCharWidth = 6.2;      // rough width of one 11-px sans-serif character, for legend layout
constexpr double kBoldCharWidth = 7.0;  // the same, bold (panel titles)

struct Series {
  const char* label;
  const char* colour;
  double (*value)(const BenchFrame&);
  double width = 1.2;  // stroke width: a wide pale line under a thin one keeps both visible where equal
};

struct Panel {
  const char* title;
  std::vector<Series> series;
  bool logScale = false;
  bool budgetLine = false;  // the 33.3 ms line (and the axis always reaches it)
};

double metricValue(const char* name, const BenchFrame& f) { return benchMetric(name).value(f); }

std::vector<Panel> timelinePanels() {
  // Colour-blind-safe-ish (Tableau 10); one colour per role so panels read alike.
  return {
      // gpu_ms is often equal to frame_ms (lavapipe): drawn wide and pale underneath, frame_ms on top.
      {"Frame time (ms)",
       {{"gpu_ms", "#98df8a", [](const BenchFrame& f) { return metricValue("gpu_ms", f); }, 3.5},
        {"select_ms", "#ff7f0e", [](const BenchFrame& f) { return metricValue("select_ms", f); }},
        {"frame_ms", "#1f77b4", [](const BenchFrame& f) { return metricValue("frame_ms", f); }}},
       false,
       true},
      {"GPU time by pass (ms)",
       {{"gpu_terrain_ms", "#2ca02c", [](const BenchFrame& f) { return metricValue("gpu_terrain_ms", f); }},
        {"gpu_skirts_ms", "#9467bd", [](const BenchFrame& f) { return metricValue("gpu_skirts_ms", f); }},
        {"gpu_sky_ms", "#17becf", [](const BenchFrame& f) { return metricValue("gpu_sky_ms", f); }},
        {"gpu_shadows_ms", "#8c564b", [](const BenchFrame& f) { return metricValue("gpu_shadows_ms", f); }},
        {"gpu_generation_ms", "#d62728", [](const BenchFrame& f) { return metricValue("gpu_generation_ms", f); }}}},
      {"Nodes drawn",
       {{"nodes_selected", "#1f77b4", [](const BenchFrame& f) { return metricValue("nodes_selected", f); }},
        {"nodes_partial", "#d62728", [](const BenchFrame& f) { return metricValue("nodes_partial", f); }},
        {"draw_calls", "#7f7f7f", [](const BenchFrame& f) { return metricValue("draw_calls", f); }}}},
      {"Triangles", {{"triangles", "#9467bd", [](const BenchFrame& f) { return metricValue("triangles", f); }}}},
      {"Generation per frame",
       {{"gen_dispatched", "#1f77b4", [](const BenchFrame& f) { return metricValue("gen_dispatched", f); }},
        {"gen_completed", "#2ca02c", [](const BenchFrame& f) { return metricValue("gen_completed", f); }},
        {"evicted", "#d62728", [](const BenchFrame& f) { return metricValue("evicted", f); }}}},
      {"Generation in flight and queued",
       {{"gen_in_flight", "#ff7f0e", [](const BenchFrame& f) { return metricValue("gen_in_flight", f); }},
        // Not a CSV column (the column list is fixed by the issue), but it is what makes dispatches wait.
        {"queue_length", "#8c564b", [](const BenchFrame& f) { return static_cast<double>(f.stats.queue_length); }}}},
      {"Resident payload memory (MiB)",
       {{"resident_mib", "#17becf", [](const BenchFrame& f) { return metricValue("resident_mib", f); }}}},
      {"Altitude (m, log scale)",
       {{"altitude_m", "#8c564b", [](const BenchFrame& f) { return metricValue("altitude_m", f); }}},
       true},
  };
}

std::string num(double v) { return svgNumber(v); }

// Multiples of a nice step within [t0, t1], computed from an integer index so they don't drift.
std::vector<double> timeTicks(double t0, double t1, double& step) {
  step = niceStep(t1 - t0, 10);
  std::vector<double> ticks;
  for (double k = std::ceil(t0 / step - 1e-9); k * step <= t1 + 1e-9 * step; k += 1) ticks.push_back(k * step);
  return ticks;
}

std::string lengthLabel(double metres) {
  return metres >= 1000 ? formatFixed(metres / 1000, 0) + " km" : formatFixed(metres, 0) + " m";
}

// Which frames a series is drawn through: all of them, or each bucket's min and max in frame order.
std::vector<std::size_t> plottedFrames(const std::vector<double>& values) {
  const std::size_t n = values.size();
  std::vector<std::size_t> indices;
  if (n <= kTimelineMaxPoints) {
    indices.resize(n);
    for (std::size_t i = 0; i < n; ++i) indices[i] = i;
    return indices;
  }
  const std::size_t buckets = kTimelineMaxPoints / 2;
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t begin = b * n / buckets;
    const std::size_t end = (b + 1) * n / buckets;
    std::size_t lo = begin;
    std::size_t hi = begin;
    for (std::size_t i = begin; i < end; ++i) {
      if (values[i] < values[lo]) lo = i;
      if (values[i] > values[hi]) hi = i;
    }
    indices.push_back(std::min(lo, hi));
    if (lo != hi) indices.push_back(std::max(lo, hi));
  }
  return indices;
}

struct XAxis {
  double t0 = 0;
  double t1 = 1;
  double x(double t) const { return kLeft + (t - t0) / (t1 - t0) * kPlotWidth; }
};

class PanelWriter {
 public:
  PanelWriter(std::string& out, const XAxis& xAxis, std::span<const BenchFrame> frames,
              std::span<const BenchKeyFrame> keyFrames)
      : out_(out), xAxis_(xAxis), frames_(frames), keyFrames_(keyFrames) {}

  void write(const Panel& panel, std::size_t index, double top, bool labelKeyFrames) {
    const double plotTop = top + kPanelHeader;
    const double plotBottom = plotTop + kPlotHeight;
    std::vector<std::vector<double>> values(panel.series.size());
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      values[s].reserve(frames_.size());
      for (const BenchFrame& f : frames_) values[s].push_back(panel.series[s].value(f));
    }
    std::string note;
    const auto y =
        panel.logScale ? logAxis(values, plotTop, plotBottom) : linearAxis(panel, values, plotTop, plotBottom, note);

    const std::string clipId = "globe-timeline-clip-" + std::to_string(index);
    out_ += "<clipPath id=\"" + clipId + "\"><rect x=\"" + num(kLeft) + "\" y=\"" + num(plotTop) + "\" width=\"" +
            num(kPlotWidth) + "\" height=\"" + num(kPlotHeight) + "\"/></clipPath>\n";
    verticalGrid(plotTop, plotBottom, labelKeyFrames);
    for (std::size_t s = 0; s < panel.series.size(); ++s) series(panel.series[s], values[s], y, clipId);
    if (panel.budgetLine) {  // over the series, and its label on a white halo, so both stay readable
      const double yb = y(kFrameBudgetMs);
      out_ += "<line x1=\"" + num(kLeft) + "\" y1=\"" + num(yb) + "\" x2=\"" + num(kLeft + kPlotWidth) + "\" y2=\"" +
              num(yb) + "\" stroke=\"#d62728\" stroke-width=\"1\" stroke-dasharray=\"6 3\"/>\n";
      out_ += "<text x=\"" + num(kLeft + kPlotWidth - 4) + "\" y=\"" + num(yb - 3) +
              "\" text-anchor=\"end\" fill=\"#d62728\" font-size=\"10\" stroke=\"#ffffff\" stroke-width=\"3\" "
              "paint-order=\"stroke\">33.3 ms (30 fps)</text>\n";
    }
    out_ += "<rect x=\"" + num(kLeft) + "\" y=\"" + num(plotTop) + "\" width=\"" + num(kPlotWidth) + "\" height=\"" +
            num(kPlotHeight) + "\" fill=\"none\" stroke=\"#444\" stroke-width=\"1\"/>\n";
    header(panel, top, note);
  }

 private:
  using YMap = std::function<double(double)>;

  YMap linearAxis(const Panel& panel, const std::vector<std::vector<double>>& values, double plotTop, double plotBottom,
                  std::string& note) {
    // One first-frame shader compile can be 100x a normal frame; scaling the axis to it would flatten
    // everything else, so the axis stops at 1.5 x the largest p99 and says what it clipped.
    double top = 0;
    double robustTop = 0;
    for (const auto& v : values) {
      std::vector<double> sorted = v;
      std::sort(sorted.begin(), sorted.end());
      top = std::max(top, sorted.back());
      robustTop = std::max(robustTop, 1.5 * nearestRankPercentile(sorted, 99));
    }
    if (panel.budgetLine) robustTop = std::max(robustTop, kFrameBudgetMs * 1.15);
    double axisTop = top;
    if (top > robustTop && robustTop > 0) {
      axisTop = robustTop;
      note = "clipped above the axis; max " + tickLabel(top, niceStep(top, 100));
    }
    if (panel.budgetLine) axisTop = std::max(axisTop, kFrameBudgetMs * 1.15);
    if (!(axisTop > 0)) axisTop = 1;
    const double step = niceStep(axisTop, 4);
    const double yMax = std::ceil(axisTop / step - 1e-9) * step;
    const YMap y = [=](double v) { return plotBottom - v / yMax * (plotBottom - plotTop); };
    for (int i = 0; i * step <= yMax * (1 + 1e-9); ++i) tick(y(i * step), tickLabel(i * step, step), plotTop);
    return y;
  }

  YMap logAxis(const std::vector<std::vector<double>>& values, double plotTop, double plotBottom) {
    // Heights below 1 m (or at/below the ground) are drawn at 1 m: a log axis has no zero.
    double lo = 1e300;
    double hi = 1;
    for (const auto& v : values) {
      for (double x : v) {
        lo = std::min(lo, std::max(x, 1.0));
        hi = std::max(hi, x);
      }
    }
    const double d0 = std::floor(std::log10(lo));
    double d1 = std::ceil(std::log10(hi));
    if (d1 <= d0) d1 = d0 + 1;
    const YMap y = [=](double v) {
      return plotBottom - (std::log10(std::max(v, 1.0)) - d0) / (d1 - d0) * (plotBottom - plotTop);
    };
    const int decades = static_cast<int>(d1 - d0);
    const int every = decades > 6 ? 2 : 1;
    for (int d = 0; d <= decades; ++d) {
      const double v = std::pow(10.0, d0 + d);
      tick(y(v), d % every == 0 ? lengthLabel(v) : std::string(), plotTop);
    }
    return y;
  }

  // A horizontal grid line with its label at the left.
  void tick(double y, const std::string& label, double plotTop) {
    if (y < plotTop - 0.5) return;
    out_ += svgHorizontalTick(y, kLeft, kLeft + kPlotWidth, label);
  }

  void verticalGrid(double plotTop, double plotBottom, bool labelKeyFrames) {
    double step = 0;
    for (double t : timeTicks(xAxis_.t0, xAxis_.t1, step)) {
      const double x = xAxis_.x(t);
      out_ += "<line x1=\"" + num(x) + "\" y1=\"" + num(plotTop) + "\" x2=\"" + num(x) + "\" y2=\"" + num(plotBottom) +
              "\" stroke=\"#e0e0e0\" stroke-width=\"1\"/>\n";
    }
    for (const BenchKeyFrame& k : keyFrames_) {
      if (k.t_s < xAxis_.t0 || k.t_s > xAxis_.t1) continue;
      const double x = xAxis_.x(k.t_s);
      out_ += "<line x1=\"" + num(x) + "\" y1=\"" + num(plotTop) + "\" x2=\"" + num(x) + "\" y2=\"" + num(plotBottom) +
              "\" stroke=\"#999\" stroke-width=\"1\" stroke-dasharray=\"2 3\"/>\n";
      if (labelKeyFrames) {
        out_ += "<text x=\"" + num(x + 3) + "\" y=\"" + num(plotTop + 11) + "\" fill=\"#777\" font-size=\"10\">key " +
                escapeMarkup(formatFixed(k.t_s, 2)) + " s</text>\n";
      }
    }
  }

  void series(const Series& s, const std::vector<double>& values, const YMap& y, const std::string& clipId) {
    const std::vector<std::size_t> indices = plottedFrames(values);
    if (indices.size() == 1) {  // a polyline through one point draws nothing
      out_ += "<circle cx=\"" + num(xAxis_.x(frames_[0].t_s)) + "\" cy=\"" + num(y(values[0])) +
              "\" r=\"2.5\" fill=\"" + s.colour + "\"/>\n";
      return;
    }
    out_ += "<polyline fill=\"none\" stroke=\"" + std::string(s.colour) + "\" stroke-width=\"" + num(s.width) +
            "\" stroke-linejoin=\"round\" clip-path=\"url(#" + clipId + ")\" points=\"";
    for (std::size_t k = 0; k < indices.size(); ++k) {
      const std::size_t i = indices[k];
      if (k > 0) out_ += ' ';
      out_ += num(xAxis_.x(frames_[i].t_s)) + ',' + num(y(values[i]));
    }
    out_ += "\"/>\n";
  }

  // Panel title, then the legend, then any clipping note, on one line above the plot.
  void header(const Panel& panel, double top, const std::string& note) {
    const double baseline = top + kPanelHeader - 8;
    out_ += "<text x=\"" + num(kLeft) + "\" y=\"" + num(baseline) + "\" font-weight=\"bold\">" +
            escapeMarkup(panel.title) + "</text>\n";
    double x = kLeft + static_cast<double>(std::string(panel.title).size()) * kBoldCharWidth + 3 * kCharWidth;
    for (const Series& s : panel.series) {
      out_ += "<line x1=\"" + num(x) + "\" y1=\"" + num(baseline - 4) + "\" x2=\"" + num(x + 16) + "\" y2=\"" +
              num(baseline - 4) + "\" stroke=\"" + s.colour + "\" stroke-width=\"2\"/>\n";
      out_ += "<text x=\"" + num(x + 20) + "\" y=\"" + num(baseline) + "\">" + escapeMarkup(s.label) + "</text>\n";
      x += 20 + (static_cast<double>(std::string(s.label).size()) + 2) * kCharWidth;
    }
    if (!note.empty()) {
      out_ += "<text x=\"" + num(kLeft + kPlotWidth) + "\" y=\"" + num(baseline) +
              "\" text-anchor=\"end\" fill=\"#777\" font-size=\"10\">" + escapeMarkup(note) + "</text>\n";
    }
  }

  std::string& out_;
  const XAxis& xAxis_;
  std::span<const BenchFrame> frames_;
  std::span<const BenchKeyFrame> keyFrames_;
};

}  // namespace

std::string benchTimelineSvg(const BenchRunInfo& info, std::span<const BenchFrame> frames,
                             std::span<const BenchKeyFrame> keyFrames) {
  XAxis xAxis;
  xAxis.t0 = frames.front().t_s;
  xAxis.t1 = frames.back().t_s > xAxis.t0 ? frames.back().t_s : xAxis.t0 + 1;

  const std::vector<Panel> panels = timelinePanels();
  const double panelsHeight = static_cast<double>(panels.size()) * (kPanelHeader + kPlotHeight + kPanelGap);
  const double height = kTitleHeight + panelsHeight + kAxisHeight;

  std::string out;
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(kWidth) + "\" height=\"" + num(height) +
         "\" viewBox=\"0 0 " + num(kWidth) + ' ' + num(height) +
         "\" font-family=\"sans-serif\" font-size=\"11\" fill=\"#222\">\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + num(kWidth) + "\" height=\"" + num(height) + "\" fill=\"#ffffff\"/>\n";
  const std::string title = "globe bench: " + info.pathFile + " on " + info.planetFile;
  const std::string subtitle = info.mode + ", " + info.size + ", " + std::to_string(frames.size()) + " frames" +
                               (frames.size() > kTimelineMaxPoints ? " (drawn through per-bucket min and max)" : "");
  out += "<text x=\"" + num(kLeft) + "\" y=\"18\" font-size=\"14\" font-weight=\"bold\">" + escapeMarkup(title) +
         "</text>\n";
  out += "<text x=\"" + num(kLeft) + "\" y=\"33\" fill=\"#555\">" + escapeMarkup(subtitle) + "</text>\n";

  PanelWriter writer(out, xAxis, frames, keyFrames);
  double top = kTitleHeight;
  for (std::size_t p = 0; p < panels.size(); ++p) {
    writer.write(panels[p], p, top, p == 0);
    top += kPanelHeader + kPlotHeight + kPanelGap;
  }

  // The shared x axis under the last panel.
  const double axisY = top - kPanelGap;
  double step = 0;
  for (double t : timeTicks(xAxis.t0, xAxis.t1, step)) {
    const double x = xAxis.x(t);
    out += "<line x1=\"" + num(x) + "\" y1=\"" + num(axisY) + "\" x2=\"" + num(x) + "\" y2=\"" + num(axisY + 4) +
           "\" stroke=\"#444\" stroke-width=\"1\"/>\n";
    out += "<text x=\"" + num(x) + "\" y=\"" + num(axisY + 16) + "\" text-anchor=\"middle\">" +
           escapeMarkup(tickLabel(t, step)) + "</text>\n";
  }
  out += "<text x=\"" + num(kLeft + kPlotWidth / 2) + "\" y=\"" + num(axisY + 32) +
         "\" text-anchor=\"middle\">path time t (s)</text>\n";
  out += "</svg>\n";
  return out;
}

}  // namespace globe
