#include "engine/report/bench_distribution_svg.h"

#include "engine/report/bench_metrics.h"
#include "engine/report/markup_escape.h"
#include "engine/report/svg_axis.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace globe {

namespace {

constexpr double kWidth = 960;
constexpr double kHeight = 260;
constexpr double kLeft = 72;
constexpr double kRight = 16;
constexpr double kTop = 30;
constexpr double kBottom = 44;  // x tick labels and the axis title
constexpr double kPlotWidth = kWidth - kLeft - kRight;
constexpr double kPlotHeight = kHeight - kTop - kBottom;
constexpr std::size_t kMaxPoints = 2000;  // more frames are drawn through evenly spaced ranks

std::string line(double x1, double y1, double x2, double y2, const std::string& style) {
  return "<line x1=\"" + svgNumber(x1) + "\" y1=\"" + svgNumber(y1) + "\" x2=\"" + svgNumber(x2) + "\" y2=\"" +
         svgNumber(y2) + "\" " + style + "/>\n";
}

std::string label(double x, double y, const std::string& text, const char* extra = "") {
  return "<text x=\"" + svgNumber(x) + "\" y=\"" + svgNumber(y) + "\" " + extra + ">" + escapeMarkup(text) +
         "</text>\n";
}

// The axis ends at a round value above the frame times, but, like the timeline, not at a lone
// spike (a first-frame compile): beyond 1.5 x p99 the curve runs off the right edge.
double axisEnd_ms(const std::vector<double>& sorted, double& step) {
  const double p99 = nearestRankPercentile(sorted, 99);
  const double end = std::max({std::min(sorted.back(), 1.5 * p99), kFrameBudgetMs * 1.15, 1.0});
  step = niceStep(end, 8);
  return std::ceil(end / step - 1e-9) * step;
}

}  // namespace

std::string frameTimeCdfSvg(std::span<const BenchFrame> frames) {
  std::vector<double> sorted;
  sorted.reserve(frames.size());
  for (const BenchFrame& f : frames) sorted.push_back(f.stats.frame_ms);
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  double step = 1;
  const double xMax = axisEnd_ms(sorted, step);
  const auto x = [&](double ms) { return kLeft + std::min(ms, xMax) / xMax * kPlotWidth; };
  const auto y = [&](double share) { return kTop + (1.0 - share) * kPlotHeight; };

  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + svgNumber(kWidth) + "\" height=\"" +
                    svgNumber(kHeight) + "\" viewBox=\"0 0 " + svgNumber(kWidth) + ' ' + svgNumber(kHeight) +
                    "\" font-family=\"sans-serif\" font-size=\"11\" fill=\"#222\">\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + svgNumber(kWidth) + "\" height=\"" + svgNumber(kHeight) +
         "\" fill=\"#ffffff\"/>\n";
  out +=
      label(kLeft, 18, "Frame-time distribution: share of frames at or below each frame time", "font-weight=\"bold\"");
  for (int pct = 0; pct <= 100; pct += 25) {
    out += svgHorizontalTick(y(pct / 100.0), kLeft, kLeft + kPlotWidth, std::to_string(pct) + " %");
  }
  for (double v = 0; v <= xMax * (1 + 1e-9); v += step) {
    out += line(x(v), kTop, x(v), kTop + kPlotHeight, "stroke=\"#e0e0e0\" stroke-width=\"1\"");
    out += label(x(v), kTop + kPlotHeight + 16, tickLabel(v, step), "text-anchor=\"middle\"");
  }
  out += label(kLeft + kPlotWidth / 2, kHeight - 8, "frame_ms (ms)", "text-anchor=\"middle\"");

  // The empirical CDF as a staircase: rank i (1-based) of n is reached at sorted[i - 1].
  const std::size_t points = std::min(n, kMaxPoints);
  out += "<polyline fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"1.5\" points=\"" + svgNumber(x(sorted[0])) + ',' +
         svgNumber(y(0));
  for (std::size_t k = 1; k <= points; ++k) {
    const std::size_t rank = k * n / points;  // 1..n
    const double ms = sorted[rank - 1];
    out += ' ' + svgNumber(x(ms)) + ',' + svgNumber(y(double(rank - 1) / double(n)));
    out += ' ' + svgNumber(x(ms)) + ',' + svgNumber(y(double(rank) / double(n)));
  }
  out += "\"/>\n";

  const double budgetX = x(kFrameBudgetMs);
  out += line(budgetX, kTop, budgetX, kTop + kPlotHeight, "stroke=\"#d62728\" stroke-dasharray=\"6 3\"");
  out += label(budgetX + 3, kTop + 12, "33.3 ms (30 fps)", "fill=\"#d62728\" font-size=\"10\"");
  for (uint32_t pct : {50u, 95u}) {
    const double v = nearestRankPercentile(sorted, pct);
    const std::string name = pct == 50 ? "median " : "p95 ";
    out += "<circle cx=\"" + svgNumber(x(v)) + "\" cy=\"" + svgNumber(y(pct / 100.0)) + "\" r=\"3\" fill=\"#222\"/>\n";
    out += label(x(v) + 5, y(pct / 100.0) + 12, name + formatFixed(v, 1) + " ms", "font-size=\"10\"");
  }
  if (sorted.back() > xMax)
    out += label(kLeft + kPlotWidth, 18, "clipped at the right; max " + formatFixed(sorted.back(), 1) + " ms",
                 "text-anchor=\"end\" fill=\"#777\" font-size=\"10\"");
  out += "<rect x=\"" + svgNumber(kLeft) + "\" y=\"" + svgNumber(kTop) + "\" width=\"" + svgNumber(kPlotWidth) +
         "\" height=\"" + svgNumber(kPlotHeight) + "\" fill=\"none\" stroke=\"#444\" stroke-width=\"1\"/>\n";
  out += "</svg>\n";
  return out;
}

}  // namespace globe
