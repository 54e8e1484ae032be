#include "engine/report/bench_phases.h"

#include "planet/analysis/percentile.h"

#include <algorithm>
#include <cmath>

namespace globe {

namespace {

constexpr double kRateWindow_s = 0.25;    // altitude and speed rates are taken over ±0.25 s
constexpr double kClimbRate_per_s = 0.1;  // ln(altitude) rising faster than 10 % per second
constexpr double kDescentRate_per_s = -0.1;
constexpr double kLowPassSpeed_per_s = 1.0;  // ground speed above one altitude per second
constexpr double kMinPhase_s = 0.5;          // shorter segments join the one before

enum Motion { kHover, kLowPass, kClimb, kDescent };

// d ln(altitude) / dt around frame i, and ground speed over altitude (both per second).
void rates(std::span<const BenchFrame> f, std::size_t i, double& logRate, double& relativeSpeed) {
  std::size_t a = i, b = i;
  while (a > 0 && f[i].t_s - f[a - 1].t_s <= kRateWindow_s) --a;
  while (b + 1 < f.size() && f[b + 1].t_s - f[i].t_s <= kRateWindow_s) ++b;
  const double dt = f[b].t_s - f[a].t_s;
  const double lo = std::max(f[a].altitude_m, 0.01), hi = std::max(f[b].altitude_m, 0.01);
  logRate = dt > 0 ? std::log(hi / lo) / dt : 0.0;
  relativeSpeed = f[i].groundSpeed_mps / std::max(f[i].altitude_m, 0.01);
}

// While the flight is still in its first descent (`approaching`), descending wins over flying fast
// (the end of an approach is low and fast); afterwards a fast, low stretch that dips is a low pass.
Motion motionAt(std::span<const BenchFrame> f, std::size_t i, bool approaching) {
  double logRate = 0, relativeSpeed = 0;
  rates(f, i, logRate, relativeSpeed);
  if (approaching && logRate < kDescentRate_per_s) return kDescent;
  if (relativeSpeed > kLowPassSpeed_per_s) return kLowPass;
  if (logRate > kClimbRate_per_s) return kClimb;
  if (logRate < kDescentRate_per_s) return kDescent;
  return kHover;
}

const char* nameOf(Motion m, bool initialDescent, bool finalClimb) {
  switch (m) {
    case kDescent:
      return initialDescent ? "approach" : "descent";
    case kLowPass:
      return "low pass";
    case kClimb:
      return finalClimb ? "exit" : "climb";
    case kHover:
      break;
  }
  return "hover";
}

}  // namespace

std::vector<FlightPhase> flightPhases(std::span<const BenchFrame> frames) {
  struct Run {
    Motion motion;
    std::size_t first, end;
  };
  std::vector<Run> runs;
  bool approaching = true;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Motion m = motionAt(frames, i, approaching);
    approaching = approaching && m == kDescent;
    if (runs.empty() || runs.back().motion != m) runs.push_back({m, i, i});
    runs.back().end = i + 1;
  }
  // Segments shorter than kMinPhase_s are noise at a transition: they join the previous one.
  std::vector<Run> merged;
  for (const Run& r : runs) {
    const bool brief = frames[r.end - 1].t_s - frames[r.first].t_s < kMinPhase_s;
    if (!merged.empty() && (brief || merged.back().motion == r.motion)) {
      merged.back().end = r.end;
    } else {
      merged.push_back(r);
    }
  }
  std::vector<FlightPhase> phases;
  for (std::size_t k = 0; k < merged.size(); ++k) {
    // A descent from the start is the approach; a climb that ends the flight is the exit.
    phases.push_back({nameOf(merged[k].motion, k == 0, k + 1 == merged.size()), merged[k].first, merged[k].end});
  }
  return phases;
}

std::vector<PhaseSummary> summarizePhases(std::span<const BenchFrame> frames) {
  std::vector<PhaseSummary> out;
  for (const FlightPhase& p : flightPhases(frames)) {
    std::vector<double> ms, nodes, triangles;
    for (std::size_t i = p.firstFrame; i < p.endFrame; ++i) {
      ms.push_back(frames[i].stats.frame_ms);
      nodes.push_back(double(frames[i].stats.nodes_selected));
      triangles.push_back(double(frames[i].stats.triangles));
    }
    for (auto* v : {&ms, &nodes, &triangles}) std::sort(v->begin(), v->end());
    PhaseSummary s{p};
    s.tStart_s = frames[p.firstFrame].t_s;
    s.tEnd_s = frames[p.endFrame - 1].t_s;
    s.frameMedian_ms = nearestRankPercentile(ms, 50);
    s.frameP95_ms = nearestRankPercentile(ms, 95);
    s.nodesMedian = nearestRankPercentile(nodes, 50);
    s.trianglesMedian = nearestRankPercentile(triangles, 50);
    out.push_back(s);
  }
  return out;
}

}  // namespace globe
