#include "engine/report/trade_report.h"

#include "engine/report/bench_metrics.h"
#include "engine/report/markup_escape.h"
#include "planet/core/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

namespace globe {

TradeRow aggregateTradeRows(const std::vector<TradeRow>& rows) {
  TradeRow w = rows.front();
  w.camera = "worst";
  w.error = {};
  double gen = 0;
  for (const TradeRow& r : rows) {
    w.frameMedian_ms = std::max(w.frameMedian_ms, r.frameMedian_ms);
    w.frameP95_ms = std::max(w.frameP95_ms, r.frameP95_ms);
    w.select_ms = std::max(w.select_ms, r.select_ms);
    w.triangles = std::max(w.triangles, r.triangles);
    w.nodes = std::max(w.nodes, r.nodes);
    w.resident_mib = std::max(w.resident_mib, r.resident_mib);
    w.converged = w.converged && r.converged;
    gen += r.genPerNode_ms;
    ScreenError& e = w.error;
    e.samples += r.error.samples;
    e.bothHit += r.error.bothHit;
    e.unresolved += r.error.unresolved;
    e.p50_px = std::max(e.p50_px, r.error.p50_px);
    e.p95_px = std::max(e.p95_px, r.error.p95_px);
    e.max_px = std::max(e.max_px, r.error.max_px);
    e.p50_m = std::max(e.p50_m, r.error.p50_m);
    e.p95_m = std::max(e.p95_m, r.error.p95_m);
    e.max_m = std::max(e.max_m, r.error.max_m);
    e.silhouetteMismatches += r.error.silhouetteMismatches;
    e.silhouetteMax_px = std::max(e.silhouetteMax_px, r.error.silhouetteMax_px);
    w.imageSsim = std::fmin(w.imageSsim, r.imageSsim);  // fmin/fmax skip a NaN (not measured)
    w.imageColourDe = std::fmax(w.imageColourDe, r.imageColourDe);
  }
  w.genPerNode_ms = gen / double(rows.size());
  return w;
}

std::vector<size_t> paretoFrontier(const std::vector<std::pair<double, double>>& points) {
  std::vector<size_t> frontier;
  for (size_t i = 0; i < points.size(); ++i) {
    bool dominated = false;
    for (size_t j = 0; j < points.size() && !dominated; ++j) {
      if (j == i) continue;
      const auto& a = points[j];
      const auto& b = points[i];
      dominated = a.first <= b.first && a.second <= b.second && (a.first < b.first || a.second < b.second);
    }
    if (!dominated) frontier.push_back(i);
  }
  std::sort(frontier.begin(), frontier.end(), [&](size_t a, size_t b) { return points[a].first < points[b].first; });
  return frontier;
}

namespace {

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

double finite(double v) { return std::isfinite(v) ? v : 0.0; }
// Empty where not measured.
std::string optional(double v, int decimals) { return std::isnan(v) ? "" : formatFixed(v, decimals); }

}  // namespace

std::string tradeCsv(const std::vector<TradeRow>& rows) {
  std::string s =
      "config,camera,grid_cells,distance_multiplier,max_depth,morph_fraction,generation,positions,lod,tolerance_px,"
      "width,height,"
      "converged,frame_median_ms,"
      "frame_p95_ms,select_ms,triangles,nodes,resident_mib,gen_ms_per_node,err_p50_px,err_p95_px,err_max_px,"
      "err_p50_m,err_p95_m,err_max_m,silhouette_mismatches,silhouette_max_px,samples,samples_both_hit,"
      "truth_unresolved,ssim,colour_de2000\n";
  for (const TradeRow& r : rows) {
    const ScreenError& e = r.error;
    s += csvField(r.config) + "," + csvField(r.camera) + "," + std::to_string(r.gridCells) + "," +
         formatFixed(r.distanceMultiplier, 3) + "," + std::to_string(r.maxDepth) + "," +
         formatFixed(r.morphFraction, 3) + "," + csvField(r.generation) + "," + csvField(r.positions) + "," +
         csvField(r.lod) + "," + formatFixed(r.tolerance_px, 3) + "," + std::to_string(r.width) + "," +
         std::to_string(r.height) + "," + (r.converged ? "1" : "0") + "," + formatFixed(r.frameMedian_ms, 3) + "," +
         formatFixed(r.frameP95_ms, 3) + "," + formatFixed(r.select_ms, 4) + "," + std::to_string(r.triangles) + "," +
         std::to_string(r.nodes) + "," + formatFixed(r.resident_mib, 3) + "," +
         formatFixed(finite(r.genPerNode_ms), 4) + "," + formatFixed(e.p50_px, 4) + "," + formatFixed(e.p95_px, 4) +
         "," + formatFixed(finite(e.max_px), 4) + "," + formatFixed(e.p50_m, 4) + "," + formatFixed(e.p95_m, 4) + "," +
         formatFixed(finite(e.max_m), 4) + "," + std::to_string(e.silhouetteMismatches) + "," +
         formatFixed(e.silhouetteMax_px, 1) + "," + std::to_string(e.samples) + "," + std::to_string(e.bothHit) + "," +
         std::to_string(e.unresolved) + "," + optional(r.imageSsim, 4) + "," + optional(r.imageColourDe, 2) + "\n";
  }
  return s;
}

namespace {

// What a Pareto plot puts in y: a per-row error (log scale), its title and a dashed goal line.
struct ParetoAxis {
  double (*value)(const TradeRow&);
  const char* title;
  double goal;
  double floor;  // smallest value drawn (a perfect row sits on it)
};

const ParetoAxis kGeometricAxis{[](const TradeRow& r) { return r.error.p95_px; },
                                "p95 screen error at the worst camera (px, log)", 0.5, 1e-4};
const ParetoAxis kImageAxis{[](const TradeRow& r) { return 1.0 - r.imageSsim; },
                            "1 - SSIM of luma against exact, worst camera (log)", 0.05, 1e-4};

// The plot's frame (px) and axes: linear frame time (ms) in x, log error in y.
struct ParetoPlot {
  static constexpr double W = 900, H = 600, left = 80, right = 30, top = 50, bottom = 60;
  double maxX = 1, step = 1, minY = 1e-3, maxY = 1;
  int ticks = 1;

  double sx(double x) const { return left + x / maxX * (W - left - right); }
  double sy(double y) const {
    double ly = std::log10(std::max(y, minY));
    return top + (1.0 - (ly - std::log10(minY)) / (std::log10(maxY) - std::log10(minY))) * (H - top - bottom);
  }
};

std::string f1(double v) { return formatFixed(v, 1); }

ParetoPlot paretoPlot(const std::vector<const TradeRow*>& pts, const ParetoAxis& axis) {
  ParetoPlot plot;
  double maxX = 1, maxY = axis.goal * 2.0;
  for (const TradeRow* r : pts) {
    maxX = std::max(maxX, r->frameMedian_ms);
    maxY = std::max(maxY, axis.value(*r));
  }
  // Round ticks: a 1-2-5 step giving at most 10 intervals; labels need room on the right.
  double step = std::pow(10.0, std::floor(std::log10(maxX * 1.15 / 10.0)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (maxX * 1.15 / (m * step) <= 10.0) {
      step *= m;
      break;
    }
  plot.step = step;
  plot.ticks = int(std::ceil(maxX * 1.15 / step));
  plot.maxX = plot.ticks * step;
  // Log error axis: whole decades from the smallest point (at most a fifth of the goal) to above the largest.
  double lo = 1e9;
  for (const TradeRow* r : pts) lo = std::min(lo, std::max(axis.value(*r), axis.floor));
  plot.minY = std::pow(10.0, std::floor(std::log10(std::min(lo, axis.goal / 5.0))));
  plot.maxY = std::pow(10.0, std::ceil(std::log10(maxY * 1.01)));
  return plot;
}

// Grid, tick labels, axis titles and the two dashed goal lines.
std::string paretoAxesSvg(const ParetoPlot& p, const ParetoAxis& axis) {
  const double W = p.W, H = p.H, left = p.left, right = p.right, top = p.top, bottom = p.bottom;
  std::string s = "<g stroke=\"#ccc\">\n";
  for (int i = 0; i <= p.ticks; ++i) {
    double x = p.step * i;
    s += "<line x1=\"" + f1(p.sx(x)) + "\" y1=\"" + f1(top) + "\" x2=\"" + f1(p.sx(x)) + "\" y2=\"" + f1(H - bottom) +
         "\"/>\n";
  }
  for (double y = p.minY; y <= p.maxY * 1.0001; y *= 10)
    s += "<line x1=\"" + f1(left) + "\" y1=\"" + f1(p.sy(y)) + "\" x2=\"" + f1(W - right) + "\" y2=\"" + f1(p.sy(y)) +
         "\"/>\n";
  s += "</g>\n<g>\n";
  for (int i = 0; i <= p.ticks; ++i) {
    double x = p.step * i;
    s += "<text x=\"" + f1(p.sx(x)) + "\" y=\"" + f1(H - bottom + 16) + "\" text-anchor=\"middle\">" +
         formatFixed(x, 0) + "</text>\n";
  }
  for (double y = p.minY; y <= p.maxY * 1.0001; y *= 10)
    s += "<text x=\"" + f1(left - 6) + "\" y=\"" + f1(p.sy(y) + 4) + "\" text-anchor=\"end\">" +
         formatFixed(y, std::max(0, int(-std::floor(std::log10(y) + 1e-9)))) + "</text>\n";
  s += "<text x=\"" + f1((left + W - right) / 2) + "\" y=\"" + f1(H - 18) +
       "\" text-anchor=\"middle\">median frame time at the slowest camera (ms, converged)</text>\n";
  s += "<text transform=\"translate(20," + f1((top + H - bottom) / 2) + ") rotate(-90)\" text-anchor=\"middle\">" +
       axis.title + "</text>\n";
  // The 33.3 ms budget and the axis's goal.
  s += "<line x1=\"" + f1(p.sx(kFrameBudgetMs)) + "\" y1=\"" + f1(top) + "\" x2=\"" + f1(p.sx(kFrameBudgetMs)) +
       "\" y2=\"" + f1(H - bottom) + "\" stroke=\"#c33\" stroke-dasharray=\"5,4\"/>\n";
  if (axis.goal >= p.minY && axis.goal <= p.maxY)
    s += "<line x1=\"" + f1(left) + "\" y1=\"" + f1(p.sy(axis.goal)) + "\" x2=\"" + f1(W - right) + "\" y2=\"" +
         f1(p.sy(axis.goal)) + "\" stroke=\"#36c\" stroke-dasharray=\"5,4\"/>\n";
  s += "</g>\n";
  return s;
}

// The frontier polyline and every configuration as a labelled point (frontier points bold).
std::string paretoPointsSvg(const ParetoPlot& p, const std::vector<const TradeRow*>& pts, const ParetoAxis& axis) {
  std::string s;
  std::vector<std::pair<double, double>> xy;
  for (const TradeRow* r : pts) xy.emplace_back(r->frameMedian_ms, std::max(axis.value(*r), axis.floor));
  std::vector<size_t> front = paretoFrontier(xy);
  if (!front.empty()) {
    s += "<polyline fill=\"none\" stroke=\"#d62\" stroke-width=\"2\" points=\"";
    for (size_t i : front) s += f1(p.sx(xy[i].first)) + "," + f1(p.sy(xy[i].second)) + " ";
    s += "\"/>\n";
  }
  for (size_t i = 0; i < pts.size(); ++i) {
    bool onFront = std::find(front.begin(), front.end(), i) != front.end();
    s += "<circle cx=\"" + f1(p.sx(xy[i].first)) + "\" cy=\"" + f1(p.sy(xy[i].second)) + "\" r=\"" +
         (onFront ? "5" : "3.5") + "\" fill=\"" + (onFront ? "#d62" : "#888") + "\"/>\n";
    s += "<text x=\"" + f1(p.sx(xy[i].first) + 7) + "\" y=\"" + f1(p.sy(xy[i].second) - 5) + "\"" +
         (onFront ? " font-weight=\"bold\"" : "") + ">" + escapeMarkup(pts[i]->config) + "</text>\n";
  }
  return s;
}

// The "worst" rows with a value on `axis`, plotted.
std::string paretoSvgOn(const std::vector<TradeRow>& rows, const std::string& title, const ParetoAxis& axis,
                        const std::string& goalText) {
  std::vector<const TradeRow*> pts;
  for (const TradeRow& r : rows)
    if (r.camera == "worst" && std::isfinite(axis.value(r))) pts.push_back(&r);
  const ParetoPlot plot = paretoPlot(pts, axis);
  const double W = plot.W, H = plot.H;
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                  f1(W) + "\" height=\"" + f1(H) + "\" viewBox=\"0 0 " + f1(W) + " " + f1(H) +
                  "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s += "<text x=\"" + f1(W / 2) + "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">" + escapeMarkup(title) +
       "</text>\n";
  s += paretoAxesSvg(plot, axis);
  s += paretoPointsSvg(plot, pts, axis);
  s += "<text x=\"" + f1(W - plot.right) + "\" y=\"" + f1(plot.top - 8) +
       "\" text-anchor=\"end\" fill=\"#d62\">orange: Pareto frontier; dashed: 33.3 ms budget, " + goalText +
       "</text>\n";
  s += "</svg>\n";
  return s;
}

}  // namespace

std::string paretoSvg(const std::vector<TradeRow>& rows, const std::string& title) {
  return paretoSvgOn(rows, title, kGeometricAxis, "0.5 px");
}

std::string paretoImageSvg(const std::vector<TradeRow>& rows, const std::string& title) {
  return paretoSvgOn(rows, title, kImageAxis, "SSIM 0.95");
}

Status writeTradeReport(const std::string& dir, const std::vector<TradeRow>& rows, const std::string& title) {
  std::vector<NamedContent> outputs{{"trade.csv", tradeCsv(rows)}, {"pareto.svg", paretoSvg(rows, title)}};
  if (std::any_of(rows.begin(), rows.end(), [](const TradeRow& r) { return !std::isnan(r.imageSsim); }))
    outputs.push_back({"pareto-image.svg", paretoImageSvg(rows, title)});
  return writeFilesAtomically(dir, outputs);
}

}  // namespace globe
