#pragma once
// `globe trade` output: one row per (configuration, camera) plus one aggregate row per configuration
// (camera "worst": the slowest camera's median frame time and the worst camera's errors), written as
// DIR/trade.csv and DIR/pareto.svg (error vs frame time, Pareto frontier highlighted).
// docs/tradeoffs.md describes the columns.
#include "planet/analysis/screen_error.h"
#include "planet/core/error.h"

#include <limits>
#include <string>
#include <vector>

namespace globe {

struct TradeRow {
  std::string config;  // e.g. "grid=64", "balanced"
  std::string camera;  // standard camera name, path sample, or "worst"
  uint32_t gridCells = 0;
  double distanceMultiplier = 0;
  int maxDepth = 0;
  double morphFraction = 0;
  std::string generation = "double";  // payload generation precision: "double" or "float"
  std::string positions = "stored";   // vertex positions: "stored" (payload) or "reprojected" (double, per frame)
  std::string lod = "distance";       // LOD ranges: "distance" (nominal ranges) or "tolerance" (screen error)
  double tolerance_px = 0;            // the tolerance of "tolerance" rows (pixels at this height), else 0
  bool converged = true;              // false: the pool could not hold the view (drawn coarser)
  uint32_t width = 0, height = 0;
  double frameMedian_ms = 0, frameP95_ms = 0;  // converged frames (render cost alone)
  double select_ms = 0;                        // median CPU selection time
  uint64_t triangles = 0;
  uint32_t nodes = 0;
  double resident_mib = 0;
  double genPerNode_ms = 0;  // GPU time of payload generation per node
  ScreenError error;
  // The picture against the converged `exact` image of the same camera (image_compare.h): SSIM of
  // luma and CIEDE2000 of the mean colours. NaN when not measured.
  double imageSsim = std::numeric_limits<double>::quiet_NaN();
  double imageColourDe = std::numeric_limits<double>::quiet_NaN();
};

// The "worst" row of `rows` of one configuration (non-empty): max of each time and error column,
// max triangles / memory, the lowest SSIM and largest colour difference; generation cost is the
// mean over cameras.
TradeRow aggregateTradeRows(const std::vector<TradeRow>& rows);

// Indices (into `points`, (frame ms, error px)) of the Pareto frontier: no other point is at least
// as fast and as accurate and strictly better in one. Sorted by frame time.
std::vector<size_t> paretoFrontier(const std::vector<std::pair<double, double>>& points);

std::string tradeCsv(const std::vector<TradeRow>& rows);
// Plots the "worst" rows: x = median frame time (ms), y = p95 error (px, log scale).
std::string paretoSvg(const std::vector<TradeRow>& rows, const std::string& title);
// The same in the picture: y = 1 - SSIM against `exact` at the worst camera (log scale).
std::string paretoImageSvg(const std::vector<TradeRow>& rows, const std::string& title);

// Writes DIR/trade.csv, DIR/pareto.svg and, when the rows carry image metrics, DIR/pareto-image.svg;
// all appear only if all could be written.
Status writeTradeReport(const std::string& dir, const std::vector<TradeRow>& rows, const std::string& title);

}  // namespace globe
