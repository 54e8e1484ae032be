#include "engine/report/bench_baseline.h"
#include "planet/core/input_file.h"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace globe {

namespace {

using Json = nlohmann::json;

std::string stringOr(const Json& object, const char* key) {
  return object.is_object() && object.contains(key) && object[key].is_string() ? object[key].get<std::string>() : "";
}

Result<MetricSummary> readMetric(const std::string& file, const std::string& name, const Json& m) {
  MetricSummary s;
  const std::pair<const char*, double*> stats[] = {{"min", &s.min}, {"median", &s.median}, {"p95", &s.p95},
                                                   {"p99", &s.p99}, {"max", &s.max},       {"mean", &s.mean}};
  for (const auto& [key, value] : stats) {
    if (!m.is_object() || !m.contains(key) || !m[key].is_number())
      return Error::inFileField(file, "metrics." + name + "." + key, "missing or not a number");
    *value = m[key].get<double>();
  }
  return s;
}

Result<Json> parseFile(const std::string& file) {
  Result<std::string> text = readInputFile(file, "an earlier run's summary.json");
  if (!text) {
    Error e = text.error();
    e.field = "--baseline";
    return e;
  }
  Json json = Json::parse(*text, nullptr, false);
  if (json.is_discarded()) return Error::inFileField(file, "--baseline", "not valid JSON");
  const std::string schema = stringOr(json, "schema");
  if (schema.rfind("globe-bench-summary/", 0) != 0)
    return Error::inFileField(file, "schema", "not a globe bench summary (expected \"globe-bench-summary/1\")");
  if (!json.contains("metrics") || !json["metrics"].is_object())
    return Error::inFileField(file, "metrics", "missing or not an object");
  return json;
}

}  // namespace

const MetricSummary* BenchBaseline::metric(const std::string& name) const {
  for (const auto& [key, summary] : metrics) {
    if (key == name) return &summary;
  }
  return nullptr;
}

Result<BenchBaseline> readBenchBaseline(const std::string& dir) {
  const std::string file = (std::filesystem::path(dir) / "summary.json").string();
  auto json = parseFile(file);
  if (!json) return json.error();
  BenchBaseline b;
  b.file = file;
  const Json& run = (*json).contains("run") ? (*json)["run"] : Json::object();
  b.commit = stringOr(run, "commit");
  b.dateUtc = stringOr(run, "date_utc");
  b.device = stringOr(run, "device");
  b.mode = stringOr(run, "mode");
  if ((*json).contains("jank_ms") && (*json)["jank_ms"].is_number()) b.jank_ms = (*json)["jank_ms"].get<double>();
  if ((*json).contains("frames_over_33ms") && (*json)["frames_over_33ms"].is_number_unsigned())
    b.framesOverBudget = (*json)["frames_over_33ms"].get<uint64_t>();
  const Json& metrics = (*json)["metrics"];
  for (const BenchMetric& m : benchMetrics()) {
    if (!metrics.contains(m.name)) continue;  // an older run without this column
    auto summary = readMetric(file, m.name, metrics[m.name]);
    if (!summary) return summary.error();
    b.metrics.emplace_back(m.name, *summary);
  }
  if (!b.metric("frame_ms")) return Error::inFileField(file, "metrics.frame_ms", "missing");
  return b;
}

}  // namespace globe
