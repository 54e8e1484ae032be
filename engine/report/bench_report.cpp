#include "engine/report/bench_report.h"

#include "engine/report/bench_baseline.h"
#include "engine/report/bench_metrics.h"
#include "engine/report/bench_phases.h"
#include "engine/report/bench_report_html.h"
#include "engine/report/bench_timeline_svg.h"
#include "planet/core/atomic_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

namespace globe {

namespace {

namespace fs = std::filesystem;

constexpr int kTimeDecimals = 6;  // t in seconds: microseconds, enough for any fixed step

// Bad frames are the caller's data, but a report built on them would be silently wrong
// (NaN sorts anywhere, breaks JSON and the plot), so they are refused with the offending value named.
Status validateFrames(std::span<const BenchFrame> frames) {
  if (frames.empty()) return Error::inField("frames", "no frames to report");
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::string where = "frames[" + std::to_string(i) + "]";
    if (!std::isfinite(frames[i].t_s)) return Error::inField(where + ".t_s", "not a finite number");
    if (i > 0 && frames[i].t_s < frames[i - 1].t_s) {
      return Error::inField(where + ".t_s", "time goes backwards (" + formatFixed(frames[i].t_s, kTimeDecimals) +
                                                " s after " + formatFixed(frames[i - 1].t_s, kTimeDecimals) + " s)");
    }
    for (const BenchMetric& m : benchMetrics()) {
      if (!std::isfinite(m.value(frames[i]))) return Error::inField(where + "." + m.name, "not a finite number");
    }
  }
  return Ok{};
}

Status validateKeyFrames(const std::string& dir, std::span<const BenchKeyFrame> keyFrames) {
  for (std::size_t i = 0; i < keyFrames.size(); ++i) {
    const BenchKeyFrame& k = keyFrames[i];
    const std::string where = "keyFrames[" + std::to_string(i) + "]";
    if (!std::isfinite(k.t_s)) return Error::inField(where + ".t_s", "not a finite number");
    const fs::path file(k.imageFile);
    // The report links it by this name, so it has to stay inside the report directory.
    bool escapes = file.empty() || file.is_absolute();
    for (const auto& part : file) escapes = escapes || part == "..";
    if (escapes)
      return Error::inField(where + ".imageFile",
                            "'" + k.imageFile + "' is not a file name inside the report directory");
    std::error_code ec;
    const fs::path full = fs::path(dir) / file;
    if (k.png.empty() && !fs::is_regular_file(full, ec))
      return Error::inFileField(full.string(), where + ".imageFile", "key-frame image does not exist");
  }
  return Ok{};
}

void appendCsvRow(const BenchFrame& f, std::string& out) {
  out += std::to_string(f.frame);
  out += ',';
  out += formatFixed(f.t_s, kTimeDecimals);
  for (const BenchMetric& m : benchMetrics()) {
    out += ',';
    out += m.kind == MetricKind::Integer ? std::to_string(static_cast<uint64_t>(m.value(f)))
                                         : formatFixed(m.value(f), m.decimals);
  }
  out += '\n';
}

// frames.csv streamed in pieces of ~64 KiB: never the whole table in memory.
void writeFramesCsv(std::span<const BenchFrame> frames, CheckedFileWriter& file) {
  constexpr std::size_t kChunkBytes = 64 << 10;
  std::string chunk = "frame,t";
  for (const BenchMetric& m : benchMetrics()) chunk += std::string(",") + m.name;
  chunk += '\n';
  for (const BenchFrame& f : frames) {
    appendCsvRow(f, chunk);
    if (chunk.size() < kChunkBytes) continue;
    if (!file.write(chunk)) return;
    chunk.clear();
  }
  file.write(chunk);
}

// Integer metrics keep integer statistics (they are samples); the mean is a real number.
nlohmann::ordered_json statValue(double v, const BenchMetric& m) {
  if (m.kind == MetricKind::Integer) return static_cast<uint64_t>(v);
  return v;
}

nlohmann::ordered_json phasesJson(std::span<const BenchFrame> frames) {
  nlohmann::ordered_json phases = nlohmann::ordered_json::array();
  for (const PhaseSummary& p : summarizePhases(frames)) {
    phases.push_back({{"name", p.phase.name},
                      {"t_start_s", p.tStart_s},
                      {"t_end_s", p.tEnd_s},
                      {"frames", p.phase.endFrame - p.phase.firstFrame},
                      {"frame_ms_median", p.frameMedian_ms},
                      {"frame_ms_p95", p.frameP95_ms},
                      {"nodes_median", static_cast<uint64_t>(p.nodesMedian)},
                      {"triangles_median", static_cast<uint64_t>(p.trianglesMedian)}});
  }
  return phases;
}

// The earlier run's medians and p95s beside this run's, with ratios (this / baseline; 0 when the
// baseline's value is 0).
nlohmann::ordered_json baselineJson(const BenchBaseline& baseline, std::span<const BenchFrame> frames) {
  using Json = nlohmann::ordered_json;
  const auto ratio = [](double now, double before) { return before != 0 ? now / before : 0.0; };
  Json metrics = Json::object();
  for (const BenchMetric& m : benchMetrics()) {
    const MetricSummary* before = baseline.metric(m.name);
    if (!before) continue;
    const MetricSummary now = summarizeMetric(frames, m);
    metrics[m.name] = {{"median", before->median},
                       {"p95", before->p95},
                       {"median_ratio", ratio(now.median, before->median)},
                       {"p95_ratio", ratio(now.p95, before->p95)}};
  }
  return {{"file", baseline.file},
          {"commit", baseline.commit},
          {"date_utc", baseline.dateUtc},
          {"jank_ms", baseline.jank_ms},
          {"jank_ratio", ratio(jankMs(frames), baseline.jank_ms)},
          {"metrics", std::move(metrics)}};
}

std::string summaryJson(const BenchRunInfo& info, std::span<const BenchFrame> frames,
                        std::span<const BenchKeyFrame> keyFrames, const BenchBaseline* baseline) {
  using Json = nlohmann::ordered_json;  // keys in the order written: readable, and stable bytes
  Json run = {{"planet_file", info.planetFile},
              {"path_file", info.pathFile},
              {"mode", info.mode},
              {"device", info.device},
              {"size", info.size},
              {"grid_cells", info.gridCells},
              {"shading", info.shading},
              {"command_line", info.commandLine},
              {"globe_version", info.globeVersion},
              {"driver", info.driver},
              {"shader_cache", info.shaderCache},
              {"load_average_start", info.loadAverageStart},
              {"load_average_end", info.loadAverageEnd},
              {"commit", info.commit},
              {"date_utc", info.dateUtc}};
  Json metrics = Json::object();
  for (const BenchMetric& m : benchMetrics()) {
    const MetricSummary s = summarizeMetric(frames, m);
    metrics[m.name] = {{"unit", m.unit},
                       {"min", statValue(s.min, m)},
                       {"median", statValue(s.median, m)},
                       {"p95", statValue(s.p95, m)},
                       {"p99", statValue(s.p99, m)},
                       {"max", statValue(s.max, m)},
                       {"mean", s.mean}};
  }
  Json keys = Json::array();
  for (const BenchKeyFrame& k : keyFrames) keys.push_back({{"t_s", k.t_s}, {"image_file", k.imageFile}});
  Json summary = {{"schema", "globe-bench-summary/1"},   {"run", std::move(run)},
                  {"frame_count", frames.size()},        {"t_first_s", frames.front().t_s},
                  {"t_last_s", frames.back().t_s},       {"frame_budget_ms", kFrameBudgetMs},
                  {"jank_ms", jankMs(frames)},           {"frames_over_33ms", framesOverBudget(frames)},
                  {"percentile_method", "nearest-rank"}, {"metrics", std::move(metrics)},
                  {"key_frames", std::move(keys)}};
  summary["generation_latency_frames"] = {{"requests", info.latency.requests},
                                          {"p50", info.latency.p50_frames},
                                          {"p95", info.latency.p95_frames},
                                          {"p99", info.latency.p99_frames}};
  summary["phases"] = phasesJson(frames);
  if (baseline) summary["baseline"] = baselineJson(*baseline, frames);
  // Invalid UTF-8 in a file name or command line would make dump() throw; replace it instead.
  return summary.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace

Status writeBenchReport(const std::string& dir, const BenchRunInfo& info, std::span<const BenchFrame> frames,
                        std::span<const BenchKeyFrame> keyFrames, const BenchBaseline* baseline) {
  if (auto s = validateFrames(frames); !s) return s;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return Error::inFile(dir, "report directory does not exist");
  if (auto s = validateKeyFrames(dir, keyFrames); !s) return s;

  // Key frames first, report.html last: an existing report.html means the files it links to exist.
  std::vector<NamedContent> outputs;
  for (const BenchKeyFrame& k : keyFrames)
    if (!k.png.empty()) outputs.push_back({k.imageFile, k.png});
  try {
    const std::string svg = benchTimelineSvg(info, frames, keyFrames);
    outputs.push_back({"frames.csv", {}, [frames](CheckedFileWriter& file) { writeFramesCsv(frames, file); }});
    outputs.push_back({"summary.json", summaryJson(info, frames, keyFrames, baseline)});
    outputs.push_back({"timeline.svg", "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svg});
    outputs.push_back({"report.html", benchReportHtml(info, frames, keyFrames, svg, baseline)});
  } catch (const std::exception& e) {  // nlohmann or allocation: never out of here
    return Error::inFile(dir, std::string("cannot build the report: ") + e.what());
  }

  // A failure leaves every existing report file (key frames included) untouched.
  return writeFilesAtomically(dir, outputs);
}

}  // namespace globe
