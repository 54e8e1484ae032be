#include "engine/report/svg_axis.h"

#include "engine/report/bench_metrics.h"
#include "engine/report/markup_escape.h"

#include <algorithm>
#include <cmath>

namespace globe {

namespace {

int decimalsFor(double step) { return std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9))); }

}  // namespace

std::string svgNumber(double v) { return formatFixed(v, 1); }

double niceStep(double range, double targetTicks) {
  if (!(range > 0)) return 1;
  const double raw = range / targetTicks;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normalised = raw / magnitude;
  const double factor = normalised < 1.5 ? 1 : normalised < 3 ? 2 : normalised < 7 ? 5 : 10;
  return factor * magnitude;
}

std::string tickLabel(double value, double step) {
  if (value == 0) return "0";
  if (step >= 1e6) return formatFixed(value / 1e6, decimalsFor(step / 1e6)) + "M";
  if (step >= 1e3) return formatFixed(value / 1e3, decimalsFor(step / 1e3)) + "k";
  return formatFixed(value, decimalsFor(step));
}

std::string svgHorizontalTick(double y, double left, double right, const std::string& label) {
  std::string out = "<line x1=\"" + svgNumber(left) + "\" y1=\"" + svgNumber(y) + "\" x2=\"" + svgNumber(right) +
                    "\" y2=\"" + svgNumber(y) + "\" stroke=\"#e0e0e0\" stroke-width=\"1\"/>\n";
  if (!label.empty()) {
    out += "<text x=\"" + svgNumber(left - 5) + "\" y=\"" + svgNumber(y + 3.5) + "\" text-anchor=\"end\">" +
           escapeMarkup(label) + "</text>\n";
  }
  return out;
}

}  // namespace globe
