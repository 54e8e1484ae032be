// What the benchmark report adds so a person can decide from it: the run environment, the flight's
// phases, the frame-time distribution, the generation latency, the GPU split and --baseline. No GPU.
#include "engine/report/bench_baseline.h"
#include "engine/report/bench_distribution_svg.h"
#include "engine/report/bench_phases.h"
#include "engine/report/bench_report.h"
#include "engine/report/bench_timeline_svg.h"
#include "engine/report/run_environment.h"

#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <vector>

namespace globe {
namespace {

namespace fs = std::filesystem;
using testing::readFileBytes;
using testing::TempDir;

void writeFile(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A flyover-like flight at 60 Hz, altitude and ground speed piecewise: descend from orbit (0-4 s),
// hover at 30 m (4-7 s), fast and low (7-12 s), slow climb (12-15 s), hover (15-17 s), exit (17-20 s).
std::vector<BenchFrame> flyoverFrames() {
  std::vector<BenchFrame> frames;
  for (int i = 0; i <= 1200; ++i) {
    BenchFrame f;
    f.frame = uint64_t(i);
    f.t_s = i / 60.0;
    const double t = f.t_s;
    if (t < 4) {
      f.altitude_m = 800000.0 * std::pow(30.0 / 800000.0, t / 4);
      f.groundSpeed_mps = 100.0;
    } else if (t < 7) {
      f.altitude_m = 30;
    } else if (t < 12) {
      f.altitude_m = 500;
      f.groundSpeed_mps = 6000;
    } else if (t < 15) {
      f.altitude_m = 500 * std::pow(10.0, (t - 12) / 3);
      f.groundSpeed_mps = 50;
    } else if (t < 17) {
      f.altitude_m = 5000;
    } else {
      f.altitude_m = 5000 * std::pow(5000.0, (t - 17) / 3);
    }
    f.stats.frame_ms = t >= 7 && t < 12 ? 40.0 : 20.0 + (i % 5);
    f.stats.gpu_ms = f.stats.frame_ms;
    f.stats.gpu_terrain_ms = 0.7 * f.stats.gpu_ms;
    f.stats.gpu_skirts_ms = 0.1 * f.stats.gpu_ms;
    f.stats.gpu_sky_ms = 0.1 * f.stats.gpu_ms;
    f.stats.nodes_selected = 100 + uint32_t(i % 50);
    f.stats.triangles = 512u * f.stats.nodes_selected;
    frames.push_back(f);
  }
  return frames;
}

BenchRunInfo runInfo() {
  BenchRunInfo info;
  info.planetFile = "earthlike.toml";
  info.pathFile = "flyover.path";
  info.mode = "budgeted";
  info.device = "llvmpipe";
  info.size = "320x240";
  info.gridCells = 16;
  info.driver = "llvmpipe Mesa 22.3.6";
  info.shaderCache = "disabled (MESA_SHADER_CACHE_DISABLE=true)";
  info.loadAverageStart = "1.00 2.00 3.00";
  info.loadAverageEnd = "1.50 2.00 3.00";
  info.commit = "0123456789ab";
  info.dateUtc = "2026-12-01T16:36:56Z";
  info.latency = {1000, 1, 4, 9};
  return info;
}

TEST(BenchPhases, FlyoverLikeFlightHasItsFivePhasesInOrder) {
  const auto frames = flyoverFrames();
  std::vector<std::string> names;
  for (const FlightPhase& p : flightPhases(frames)) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"approach", "hover", "low pass", "climb", "hover", "exit"}));
  const auto phases = summarizePhases(frames);
  ASSERT_EQ(phases.size(), 6u);
  EXPECT_NEAR(phases[2].tStart_s, 7.0, 0.3);
  EXPECT_EQ(phases[2].frameMedian_ms, 40.0);  // the slow low pass stands out
  std::size_t covered = 0;
  for (const PhaseSummary& p : phases) covered += p.phase.endFrame - p.phase.firstFrame;
  EXPECT_EQ(covered, frames.size());
}

TEST(BenchPhases, OneFrameIsOnePhase) {
  const auto frames = flyoverFrames();
  EXPECT_EQ(flightPhases(std::span(frames).first(1)).size(), 1u);
}

TEST(BenchReportDecisions, SummaryHasEnvironmentLatencyPhasesAndGpuSplit) {
  TempDir dir("bench_decisions_summary");
  const auto frames = flyoverFrames();
  ASSERT_TRUE(writeBenchReport(dir.str(), runInfo(), frames, {}).ok());
  const auto json = nlohmann::json::parse(readFileBytes(dir / "summary.json"));
  for (const char* key : {"driver", "shader_cache", "load_average_start", "load_average_end", "commit", "date_utc"})
    EXPECT_TRUE(json["run"].contains(key)) << key;
  EXPECT_EQ(json["run"]["commit"], "0123456789ab");
  EXPECT_EQ(json["generation_latency_frames"]["p95"], 4);
  EXPECT_EQ(json["phases"].size(), 6u);
  EXPECT_EQ(json["phases"][2]["name"], "low pass");
  for (const char* key :
       {"gpu_terrain_ms", "gpu_skirts_ms", "gpu_sky_ms", "gpu_generation_ms", "gpu_shadows_ms", "ground_speed_mps"})
    EXPECT_TRUE(json["metrics"].contains(key)) << key;
  EXPECT_FALSE(json.contains("baseline"));
  const std::string html = readFileBytes(dir / "report.html");
  for (const char* text : {"MESA_SHADER_CACHE_DISABLE", "0123456789ab", "2026-12-01T16:36:56Z", "1.00 2.00 3.00",
                           "Frame-time distribution", "Phases of the flight", "GPU time by pass", "low pass"})
    EXPECT_NE(html.find(text), std::string::npos) << text;
}

TEST(BenchReportDecisions, BaselineGoesBesideWithRatios) {
  TempDir before("bench_decisions_baseline_before");
  TempDir after("bench_decisions_baseline_after");
  auto frames = flyoverFrames();
  ASSERT_TRUE(writeBenchReport(before.str(), runInfo(), frames, {}).ok());
  auto baseline = readBenchBaseline(before.str());
  ASSERT_TRUE(baseline.ok()) << baseline.error().format();
  EXPECT_EQ(baseline->commit, "0123456789ab");
  for (BenchFrame& f : frames) f.stats.frame_ms *= 2;  // twice as slow
  ASSERT_TRUE(writeBenchReport(after.str(), runInfo(), frames, {}, &*baseline).ok());
  const auto json = nlohmann::json::parse(readFileBytes(after / "summary.json"));
  ASSERT_TRUE(json.contains("baseline"));
  EXPECT_DOUBLE_EQ(json["baseline"]["metrics"]["frame_ms"]["median_ratio"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(json["baseline"]["metrics"]["nodes_selected"]["p95_ratio"].get<double>(), 1.0);
  EXPECT_NE(readFileBytes(after / "report.html").find("baseline median"), std::string::npos);
}

TEST(BenchReportDecisions, BadBaselineIsOneLineNamingTheFile) {
  TempDir dir("bench_decisions_baseline_bad");
  auto missing = readBenchBaseline((dir / "nothing").string());
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().format().find("nothing/summary.json: --baseline: cannot open"), std::string::npos)
      << missing.error().format();
  writeFile(dir / "summary.json", "{ not json");
  auto garbled = readBenchBaseline(dir.str());
  ASSERT_FALSE(garbled.ok());
  EXPECT_NE(garbled.error().format().find("summary.json: --baseline: not valid JSON"), std::string::npos);
  writeFile(dir / "summary.json", R"({"schema": "other/1", "metrics": {}})");
  EXPECT_EQ(readBenchBaseline(dir.str()).error().field, "schema");
  writeFile(dir / "summary.json",
            R"({"schema": "globe-bench-summary/1", "metrics": {"frame_ms": {"min": 1, "median": "x"}}})");
  auto badNumber = readBenchBaseline(dir.str());
  ASSERT_FALSE(badNumber.ok());
  EXPECT_EQ(badNumber.error().field, "metrics.frame_ms.median");
  EXPECT_EQ(badNumber.error().format().find('\n'), std::string::npos);
}

TEST(BenchReportDecisions, FrameTimeCdfMarksBudgetMedianAndP95) {
  const auto frames = flyoverFrames();
  const std::string svg = frameTimeCdfSvg(frames);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("33.3 ms (30 fps)"), std::string::npos);
  EXPECT_NE(svg.find("median "), std::string::npos);
  EXPECT_NE(svg.find("p95 40.0 ms"), std::string::npos);
  EXPECT_NE(svg.find("100 %"), std::string::npos);
}

TEST(BenchReportDecisions, FrameTimeIsDrawnOverAnEqualGpuTime) {
  // gpu_ms == frame_ms in every frame: frame_ms must come later in the file (on top) and thinner.
  const auto frames = flyoverFrames();
  const std::string svg = benchTimelineSvg(runInfo(), frames, {});
  const auto panel = svg.find("Frame time (ms)");
  const auto gpu = svg.find("stroke=\"#98df8a\" stroke-width=\"3.5\"");
  const auto frame = svg.find("stroke=\"#1f77b4\" stroke-width=\"1.2\"");
  ASSERT_NE(gpu, std::string::npos);
  ASSERT_NE(frame, std::string::npos);
  EXPECT_LT(gpu, frame);
  EXPECT_NE(panel, std::string::npos);
  EXPECT_NE(svg.find("GPU time by pass (ms)"), std::string::npos);
}

// Sets or clears environment variables for one test and puts the previous values back.
class ScopedEnvironment {
 public:
  ScopedEnvironment(std::initializer_list<const char*> names) {
    for (const char* name : names) {
      const char* value = std::getenv(name);
      saved_.push_back({name, value ? std::optional<std::string>(value) : std::nullopt});
      ::unsetenv(name);
    }
  }
  ~ScopedEnvironment() {
    for (const auto& [name, value] : saved_) {
      if (value)
        ::setenv(name, value->c_str(), 1);
      else
        ::unsetenv(name);
    }
  }

 private:
  std::vector<std::pair<const char*, std::optional<std::string>>> saved_;
};

TEST(RunEnvironment, ShaderCacheStateFollowsMesaVariables) {
  ScopedEnvironment env{"MESA_SHADER_CACHE_DISABLE", "MESA_GLSL_CACHE_DISABLE", "MESA_SHADER_CACHE_DIR"};
  EXPECT_EQ(mesaShaderCacheState(), "enabled");
  ::setenv("MESA_SHADER_CACHE_DIR", "/tmp/cache", 1);
  EXPECT_EQ(mesaShaderCacheState(), "enabled (MESA_SHADER_CACHE_DIR=/tmp/cache)");
  ::setenv("MESA_GLSL_CACHE_DISABLE", "1", 1);
  EXPECT_EQ(mesaShaderCacheState(), "disabled (MESA_GLSL_CACHE_DISABLE=1)");
  ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  EXPECT_EQ(mesaShaderCacheState(), "disabled (MESA_SHADER_CACHE_DISABLE=true)");
  ::setenv("MESA_SHADER_CACHE_DISABLE", "false", 1);
  EXPECT_EQ(mesaShaderCacheState(), "disabled (MESA_GLSL_CACHE_DISABLE=1)");
}

TEST(RunEnvironment, LoadAverageAndDateHaveTheirFormats) {
  const std::string load = loadAverage();
  EXPECT_TRUE(load == "unknown" || std::count(load.begin(), load.end(), ' ') == 2) << load;
  const std::string date = utcNowIso8601();
  ASSERT_EQ(date.size(), 20u) << date;
  EXPECT_EQ(date[4], '-');
  EXPECT_EQ(date[10], 'T');
  EXPECT_EQ(date.back(), 'Z');
}

}  // namespace
}  // namespace globe
