// globe trade's report: the Pareto frontier, the aggregate row, and well-formed CSV / SVG.
#include "engine/report/trade_report.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace globe {
namespace {

TEST(TradeReport, ParetoFrontierKeepsOnlyUndominatedPointsSortedByTime) {
  // (ms, px): b dominates c; d equals nothing; e is slower and worse than a.
  std::vector<std::pair<double, double>> p = {{10, 2.0}, {20, 0.5}, {25, 0.6}, {40, 0.1}, {12, 3.0}, {20, 0.5}};
  std::vector<size_t> f = paretoFrontier(p);
  // The two identical points (1 and 5) do not dominate each other: both stay.
  EXPECT_EQ(f, (std::vector<size_t>{0, 1, 5, 3}));
}

TEST(TradeReport, WorstRowAndFiles) {
  TradeRow a;
  a.config = "g16 x1 d20 f0.5";
  a.camera = "1km";
  a.gridCells = 16;
  a.frameMedian_ms = 30;
  a.error.p95_px = 0.7;
  a.error.silhouetteMismatches = 2;
  a.genPerNode_ms = 1;
  TradeRow b = a;
  b.camera = "10km";
  b.frameMedian_ms = 20;
  b.error.p95_px = 0.9;
  b.genPerNode_ms = 3;
  b.converged = false;  // a view the pool could not hold makes the configuration's worst row unconverged
  TradeRow w = aggregateTradeRows({a, b});
  EXPECT_FALSE(w.converged);
  EXPECT_EQ(w.camera, "worst");
  EXPECT_EQ(w.frameMedian_ms, 30);
  EXPECT_EQ(w.error.p95_px, 0.9);
  EXPECT_EQ(w.error.silhouetteMismatches, 4u);
  EXPECT_EQ(w.genPerNode_ms, 2);
  std::string csv = tradeCsv({a, b, w});
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
  EXPECT_NE(csv.find("g16 x1 d20 f0.5,worst,16,"), std::string::npos);
  std::string svg = paretoSvg({a, b, w}, "t <&>");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("t &lt;&amp;&gt;"), std::string::npos);
}

// The picture's columns: the worst row takes the lowest SSIM and the largest colour difference; a
// row without them leaves the cells empty; the image plot shows 1 - SSIM.
TEST(TradeReport, ImageColumnsAndPlot) {
  TradeRow a;
  a.config = "fast";
  a.camera = "1km";
  a.frameMedian_ms = 10;
  a.imageSsim = 0.8;
  a.imageColourDe = 2.5;
  TradeRow b = a;
  b.camera = "10km";
  b.imageSsim = 0.9;
  b.imageColourDe = 4.0;
  TradeRow w = aggregateTradeRows({a, b});
  EXPECT_DOUBLE_EQ(w.imageSsim, 0.8);
  EXPECT_DOUBLE_EQ(w.imageColourDe, 4.0);
  const std::string csv = tradeCsv({a, w});
  EXPECT_NE(csv.find(",truth_unresolved,ssim,colour_de2000\n"), std::string::npos);
  EXPECT_NE(csv.find(",0.8000,2.50\n"), std::string::npos);
  TradeRow none;
  none.config = "old";
  EXPECT_NE(tradeCsv({none}).find(",,\n"), std::string::npos);
  const std::string svg = paretoImageSvg({a, b, w}, "image");
  EXPECT_NE(svg.find("1 - SSIM"), std::string::npos);
  EXPECT_NE(svg.find(">fast</text>"), std::string::npos);
}

}  // namespace
}  // namespace globe
