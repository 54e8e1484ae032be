// The benchmark report writer: files, formats, statistics, well-formed markup, determinism and
// errors. No GPU.
#include "engine/report/bench_report.h"
#include "engine/io/image_io.h"
#include "engine/report/bench_metrics.h"
#include "engine/report/markup_escape.h"

#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace globe {
namespace {

namespace fs = std::filesystem;
using testing::readFileBytes;
using testing::TempDir;

const char* const kReportFiles[] = {"frames.csv", "summary.json", "timeline.svg", "report.html"};

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string line; std::getline(ss, line);) out.push_back(line);
  return out;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string field; std::getline(ss, field, sep);) out.push_back(field);
  return out;
}

// A flight-like synthetic run at 60 Hz: descent, hover, climb; frame time with one big spike.
std::vector<BenchFrame> syntheticFrames(std::size_t count) {
  std::vector<BenchFrame> frames(count);
  for (std::size_t i = 0; i < count; ++i) {
    BenchFrame& f = frames[i];
    const double t = static_cast<double>(i) / 60.0;
    f.frame = i;
    f.t_s = t;
    f.altitude_m = 800000.0 * std::exp(-t) + 30.0 + 10.0 * std::sin(t);
    f.stats.frame_ms = (i == 0 ? 250.0 : 12.0 + 30.0 * std::sin(t * 0.7) * std::sin(t * 0.7));
    f.stats.select_ms = 2.0 + 0.5 * std::cos(t);
    f.stats.gpu_ms = 8.0 + std::sin(t * 3.0);
    f.stats.nodes_selected = static_cast<uint32_t>(100 + (i * 7) % 400);
    f.stats.nodes_partial = static_cast<uint32_t>((i * 3) % 20);
    f.stats.triangles = uint64_t{32768} * f.stats.nodes_selected;
    f.stats.draw_calls = f.stats.nodes_selected;
    f.stats.gen_dispatched = static_cast<uint32_t>(i % 9);
    f.stats.gen_in_flight = static_cast<uint32_t>(i % 33);
    f.stats.gen_completed = static_cast<uint32_t>((i + 4) % 9);
    f.stats.evicted = static_cast<uint32_t>(i % 50 == 0 ? 12 : 0);
    f.stats.resident_mib = 64.0 + 0.25 * static_cast<double>(i % 400);
    f.stats.queue_length = static_cast<uint32_t>(i % 70);
  }
  return frames;
}

BenchRunInfo runInfo() {
  BenchRunInfo info;
  info.planetFile = "assets/planets/earthlike.toml";
  info.pathFile = "assets/paths/flyover.path";
  info.mode = "budgeted";
  info.device = "llvmpipe (LLVM 15.0.6, 256 bits)";
  info.size = "1280x720";
  info.gridCells = 64;
  info.shading = "aa none, normal map scale 0, atmosphere sky";
  info.commandLine = "globe bench --planet assets/planets/earthlike.toml --path assets/paths/flyover.path --out out";
  info.globeVersion = "0.1.0";
  return info;
}

// Writes tiny PNGs into `dir` at the given times.
std::vector<BenchKeyFrame> keyFramesIn(const TempDir& dir, std::vector<double> times) {
  std::vector<BenchKeyFrame> keys;
  ImageRgba image;
  image.width = 2;
  image.height = 2;
  image.rgba.assign(16, 0.5f);
  for (double t : times) {
    BenchKeyFrame k{t, "frame_t" + std::to_string(static_cast<int>(t)) + ".png"};
    EXPECT_TRUE(writePng((dir / k.imageFile).string(), image).ok());
    keys.push_back(k);
  }
  return keys;
}

// ---------------------------------------------------------------------------------------------
// A small XML well-formedness checker: balanced tags, one root, quoted unique attributes, only
// XML's five named entities and numeric references, no stray '<' or '&'. Enough for XHTML/SVG we
// write ourselves; not a validating parser.
struct XmlReport {
  std::string error;  // "" when well-formed
  std::string root;
  std::map<std::string, int> elements;  // element name -> count
};

class XmlChecker {
 public:
  explicit XmlChecker(std::string_view doc) : doc_(doc) {}

  XmlReport run() {
    XmlReport report;
    std::vector<std::string> stack;
    bool rootDone = false;
    while (pos_ < doc_.size() && report.error.empty()) {
      if (starts("<?")) {
        if (!skipPast("?>")) return fail(report, "unterminated processing instruction");
      } else if (starts("<!--")) {
        if (!skipPast("-->")) return fail(report, "unterminated comment");
      } else if (starts("<!DOCTYPE")) {
        if (!stack.empty() || !report.root.empty()) return fail(report, "DOCTYPE after the root");
        if (!skipPast(">")) return fail(report, "unterminated DOCTYPE");
      } else if (starts("</")) {
        pos_ += 2;
        const std::string name = readName();
        skipSpace();
        if (!starts(">")) return fail(report, "bad end tag");
        ++pos_;
        if (stack.empty() || stack.back() != name) return fail(report, "end tag </" + name + "> does not match");
        stack.pop_back();
        if (stack.empty()) rootDone = true;
      } else if (starts("<")) {
        ++pos_;
        const std::string name = readName();
        if (name.empty()) return fail(report, "'<' not starting a tag");
        if (rootDone || (stack.empty() && !report.root.empty())) return fail(report, "second root element");
        if (report.root.empty()) report.root = name;
        ++report.elements[name];
        std::set<std::string> attributes;
        bool selfClosing = false;
        for (;;) {
          const bool spaced = skipSpace();
          if (starts("/>")) {
            pos_ += 2;
            selfClosing = true;
            break;
          }
          if (starts(">")) {
            ++pos_;
            break;
          }
          if (!spaced) return fail(report, "no space before attribute in <" + name + ">");
          const std::string attribute = readName();
          if (attribute.empty()) return fail(report, "bad attribute in <" + name + ">");
          if (!attributes.insert(attribute).second) return fail(report, "duplicate attribute " + attribute);
          skipSpace();
          if (!starts("=")) return fail(report, "attribute without '='");
          ++pos_;
          skipSpace();
          if (pos_ >= doc_.size() || (doc_[pos_] != '"' && doc_[pos_] != '\''))
            return fail(report, "unquoted attribute");
          const char quote = doc_[pos_++];
          const std::size_t end = doc_.find(quote, pos_);
          if (end == std::string_view::npos) return fail(report, "unterminated attribute");
          const std::string_view value = doc_.substr(pos_, end - pos_);
          if (value.find('<') != std::string_view::npos) return fail(report, "'<' in attribute value");
          if (!entitiesValid(value)) return fail(report, "bad entity in attribute value");
          pos_ = end + 1;
        }
        if (!selfClosing) stack.push_back(name);
        if (selfClosing && stack.empty()) rootDone = true;
      } else {
        const std::size_t end = std::min(doc_.find('<', pos_), doc_.size());
        const std::string_view text = doc_.substr(pos_, end - pos_);
        if (stack.empty() && text.find_first_not_of(" \t\r\n") != std::string_view::npos)
          return fail(report, "text outside the root element");
        if (!entitiesValid(text)) return fail(report, "bad entity or '&' in text");
        pos_ = end;
      }
    }
    if (!report.error.empty()) return report;
    if (!stack.empty()) return fail(report, "unclosed <" + stack.back() + ">");
    if (report.root.empty()) return fail(report, "no root element");
    return report;
  }

 private:
  bool starts(std::string_view s) const { return doc_.substr(pos_, s.size()) == s; }
  bool skipPast(std::string_view s) {
    const std::size_t end = doc_.find(s, pos_);
    if (end == std::string_view::npos) return false;
    pos_ = end + s.size();
    return true;
  }
  bool skipSpace() {
    const std::size_t start = pos_;
    while (pos_ < doc_.size() && std::string_view(" \t\r\n").find(doc_[pos_]) != std::string_view::npos) ++pos_;
    return pos_ > start;
  }
  std::string readName() {
    const std::size_t start = pos_;
    while (pos_ < doc_.size() && (std::isalnum(static_cast<unsigned char>(doc_[pos_])) || doc_[pos_] == '-' ||
                                  doc_[pos_] == '_' || doc_[pos_] == ':' || doc_[pos_] == '.')) {
      ++pos_;
    }
    return std::string(doc_.substr(start, pos_ - start));
  }
  static bool entitiesValid(std::string_view text) {
    for (std::size_t i = text.find('&'); i != std::string_view::npos; i = text.find('&', i + 1)) {
      const std::size_t end = text.find(';', i);
      if (end == std::string_view::npos) return false;
      const std::string_view name = text.substr(i + 1, end - i - 1);
      static const std::set<std::string_view> kNamed = {"amp", "lt", "gt", "quot", "apos"};
      if (kNamed.count(name) != 0) continue;
      if (name.size() >= 2 && name[0] == '#') {
        const bool hex = name[1] == 'x';
        const std::string_view digits = name.substr(hex ? 2 : 1);
        if (digits.empty()) return false;
        for (char c : digits) {
          if (!(hex ? std::isxdigit(static_cast<unsigned char>(c)) : std::isdigit(static_cast<unsigned char>(c))))
            return false;
        }
        continue;
      }
      return false;
    }
    return true;
  }
  XmlReport& fail(XmlReport& report, const std::string& message) {
    report.error = message + " at byte " + std::to_string(pos_);
    return report;
  }

  std::string_view doc_;
  std::size_t pos_ = 0;
};

XmlReport checkXml(std::string_view doc) { return XmlChecker(doc).run(); }

TEST(BenchReportXmlChecker, CatchesMalformedDocuments) {
  EXPECT_EQ(checkXml("<a><b x=\"1\"/>t &amp; &#38; &#x26;</a>").error, "");
  EXPECT_NE(checkXml("<a><b></a></b>").error, "");
  EXPECT_NE(checkXml("<a>x & y</a>").error, "");
  EXPECT_NE(checkXml("<a>&nbsp;</a>").error, "");
  EXPECT_NE(checkXml("<a x=1></a>").error, "");
  EXPECT_NE(checkXml("<a x=\"1\" x=\"2\"></a>").error, "");
  EXPECT_NE(checkXml("<a></a><b></b>").error, "");
  EXPECT_NE(checkXml("<a>").error, "");
  EXPECT_NE(checkXml("<a>1 < 2</a>").error, "");
}

// ---------------------------------------------------------------------------------------------

TEST(BenchReport, WritesAllFilesAndNothingElse) {
  TempDir dir("bench_report_all");
  const auto keys = keyFramesIn(dir, {0, 7, 12, 18});
  const auto frames = syntheticFrames(1200);
  const Status s = writeBenchReport(dir.str(), runInfo(), frames, keys);
  ASSERT_TRUE(s.ok()) << s.error().format();
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir.str())) names.insert(entry.path().filename().string());
  EXPECT_EQ(names, (std::set<std::string>{"frames.csv", "summary.json", "timeline.svg", "report.html", "frame_t0.png",
                                          "frame_t7.png", "frame_t12.png", "frame_t18.png"}));  // no temporaries left
}

TEST(BenchReport, CsvHeaderIsExactWithOneRowPerFrame) {
  TempDir dir("bench_report_csv");
  const auto frames = syntheticFrames(300);
  ASSERT_TRUE(writeBenchReport(dir.str(), runInfo(), frames, {}).ok());
  const auto rows = lines(readFileBytes(dir / "frames.csv"));
  ASSERT_EQ(rows.size(), frames.size() + 1);
  EXPECT_EQ(rows[0],
            "frame,t,altitude_m,frame_ms,select_ms,gpu_ms,nodes_selected,nodes_partial,triangles,draw_calls,"
            "gen_dispatched,gen_in_flight,gen_completed,evicted,resident_mib,ground_speed_mps,gpu_terrain_ms,"
            "gpu_skirts_ms,gpu_sky_ms,gpu_generation_ms,gpu_shadows_ms");
  for (std::size_t i = 1; i < rows.size(); ++i) ASSERT_EQ(split(rows[i], ',').size(), 21U) << rows[i];
  // Frame 2 of the synthetic run, column by column.
  const auto f = split(rows[3], ',');
  EXPECT_EQ(f[0], "2");
  EXPECT_EQ(f[1], "0.033333");
  EXPECT_NEAR(std::stod(f[2]), frames[2].altitude_m, 1e-3);
  EXPECT_NEAR(std::stod(f[3]), frames[2].stats.frame_ms, 1e-4);
  EXPECT_EQ(f[6], std::to_string(frames[2].stats.nodes_selected));
  EXPECT_EQ(f[8], std::to_string(frames[2].stats.triangles));
  EXPECT_EQ(f[14], formatFixed(frames[2].stats.resident_mib, 3));
}

TEST(BenchReport, SummaryJsonHasEveryKey) {
  TempDir dir("bench_report_json");
  const auto keys = keyFramesIn(dir, {0, 7});
  const auto frames = syntheticFrames(600);
  ASSERT_TRUE(writeBenchReport(dir.str(), runInfo(), frames, keys).ok());
  const auto json = nlohmann::json::parse(readFileBytes(dir / "summary.json"), nullptr, false);
  ASSERT_FALSE(json.is_discarded());
  for (const char* key : {"schema", "run", "frame_count", "t_first_s", "t_last_s", "frame_budget_ms", "jank_ms",
                          "frames_over_33ms", "percentile_method", "metrics", "key_frames"}) {
    EXPECT_TRUE(json.contains(key)) << key;
  }
  for (const char* key : {"planet_file", "path_file", "mode", "device", "size", "grid_cells", "shading", "command_line",
                          "globe_version"}) {
    EXPECT_TRUE(json["run"].contains(key)) << key;
  }
  EXPECT_EQ(json["run"]["grid_cells"], 64);
  EXPECT_EQ(json["run"]["shading"], "aa none, normal map scale 0, atmosphere sky");
  EXPECT_EQ(json["frame_count"], 600);
  EXPECT_EQ(json["percentile_method"], "nearest-rank");
  const std::vector<std::string> columns = {"altitude_m",     "frame_ms",          "select_ms",      "gpu_ms",
                                            "nodes_selected", "nodes_partial",     "triangles",      "draw_calls",
                                            "gen_dispatched", "gen_in_flight",     "gen_completed",  "evicted",
                                            "resident_mib",   "ground_speed_mps",  "gpu_terrain_ms", "gpu_skirts_ms",
                                            "gpu_sky_ms",     "gpu_generation_ms", "gpu_shadows_ms"};
  ASSERT_EQ(json["metrics"].size(), columns.size());
  for (const auto& c : columns) {
    ASSERT_TRUE(json["metrics"].contains(c)) << c;
    for (const char* stat : {"unit", "min", "median", "p95", "p99", "max", "mean"}) {
      EXPECT_TRUE(json["metrics"][c].contains(stat)) << c << "." << stat;
    }
    EXPECT_LE(json["metrics"][c]["min"].get<double>(), json["metrics"][c]["median"].get<double>());
    EXPECT_LE(json["metrics"][c]["median"].get<double>(), json["metrics"][c]["p95"].get<double>());
    EXPECT_LE(json["metrics"][c]["p95"].get<double>(), json["metrics"][c]["p99"].get<double>());
    EXPECT_LE(json["metrics"][c]["p99"].get<double>(), json["metrics"][c]["max"].get<double>());
  }
  EXPECT_TRUE(json["metrics"]["nodes_selected"]["p95"].is_number_integer());
  EXPECT_EQ(json["metrics"]["frame_ms"]["max"], 250.0);
  ASSERT_EQ(json["key_frames"].size(), 2U);
  EXPECT_EQ(json["key_frames"][1]["image_file"], "frame_t7.png");
}

TEST(BenchReport, NearestRankPercentiles) {
  // 1..100 in scrambled order: pk is exactly k.
  std::vector<BenchFrame> frames(100);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    frames[i].frame = i;
    frames[i].t_s = static_cast<double>(i) / 60.0;
    frames[i].stats.frame_ms = static_cast<double>((i * 37) % 100 + 1);
  }
  const MetricSummary s = summarizeMetric(frames, benchMetric("frame_ms"));
  EXPECT_EQ(s.min, 1);
  EXPECT_EQ(s.median, 50);
  EXPECT_EQ(s.p95, 95);
  EXPECT_EQ(s.p99, 99);
  EXPECT_EQ(s.max, 100);
  EXPECT_DOUBLE_EQ(s.mean, 50.5);

  const std::vector<double> ten = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  EXPECT_EQ(nearestRankPercentile(ten, 0), 1);    // rank clamps to 1
  EXPECT_EQ(nearestRankPercentile(ten, 50), 5);   // lower middle for even n
  EXPECT_EQ(nearestRankPercentile(ten, 51), 6);   // ceil(5.1) = 6
  EXPECT_EQ(nearestRankPercentile(ten, 95), 10);  // ceil(9.5) = 10
  EXPECT_EQ(nearestRankPercentile(ten, 100), 10);
  const std::vector<double> one = {42};
  EXPECT_EQ(nearestRankPercentile(one, 50), 42);
  EXPECT_EQ(nearestRankPercentile(one, 99), 42);
  std::vector<double> twoHundred(200);
  for (std::size_t i = 0; i < twoHundred.size(); ++i) twoHundred[i] = static_cast<double>(i + 1);
  EXPECT_EQ(nearestRankPercentile(twoHundred, 99), 198);
  EXPECT_EQ(nearestRankPercentile(twoHundred, 95), 190);
}

TEST(BenchReport, JankAndFramesOverBudget) {
  TempDir dir("bench_report_jank");
  const double frameMs[] = {10, 33.3, 40, 100, 33.4};
  std::vector<BenchFrame> frames(std::size(frameMs));
  for (std::size_t i = 0; i < frames.size(); ++i) {
    frames[i].frame = i;
    frames[i].t_s = static_cast<double>(i) / 60.0;
    frames[i].stats.frame_ms = frameMs[i];
  }
  EXPECT_NEAR(jankMs(frames), (40 - 33.3) + (100 - 33.3) + (33.4 - 33.3), 1e-9);
  EXPECT_EQ(framesOverBudget(frames), 3U);  // 33.3 itself is on budget
  ASSERT_TRUE(writeBenchReport(dir.str(), runInfo(), frames, {}).ok());
  const auto json = nlohmann::json::parse(readFileBytes(dir / "summary.json"));
  EXPECT_NEAR(json["jank_ms"].get<double>(), 73.5, 1e-9);
  EXPECT_EQ(json["frames_over_33ms"], 3);
  EXPECT_EQ(json["frame_budget_ms"], 33.3);
}

TEST(BenchReport, SvgAndHtmlAreWellFormedEvenWithHostileText) {
  TempDir dir("bench_report_xml");
  const auto keys = keyFramesIn(dir, {0, 7, 12, 18});
  BenchRunInfo info = runInfo();
  info.pathFile = "paths/<script>alert('x')</script> & \"quotes\".path";
  info.device = std::string("bad utf-8 \xff\xfe and a control \x01 char; ünïcödé ok");
  info.commandLine = "globe bench --out 'a&b' --path \"<x>\"";
  info.driver = "<b>driver</b> & co";
  info.shaderCache = "enabled (MESA_SHADER_CACHE_DIR=/tmp/<a&b>)";
  const auto frames = syntheticFrames(1500);
  const Status s = writeBenchReport(dir.str(), info, frames, keys);
  ASSERT_TRUE(s.ok()) << s.error().format();

  const std::string svg = readFileBytes(dir / "timeline.svg");
  const XmlReport svgCheck = checkXml(svg);
  EXPECT_EQ(svgCheck.error, "");
  EXPECT_EQ(svgCheck.root, "svg");
  EXPECT_GE(svgCheck.elements.at("polyline"), 12);  // every series of every panel
  EXPECT_NE(svg.find("33.3 ms"), std::string::npos);
  EXPECT_NE(svg.find("altitude_m"), std::string::npos);
  EXPECT_NE(svg.find("gen_in_flight"), std::string::npos);
  EXPECT_EQ(svg.find("<script>"), std::string::npos);

  const std::string html = readFileBytes(dir / "report.html");
  const XmlReport htmlCheck = checkXml(html);
  EXPECT_EQ(htmlCheck.error, "");
  EXPECT_EQ(htmlCheck.root, "html");
  EXPECT_EQ(htmlCheck.elements.at("img"), 4);
  EXPECT_EQ(htmlCheck.elements.at("svg"), 2);  // the frame-time distribution and the timeline, inlined
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  for (const char* needle : {"frame_t12.png", "t = 18.00 s", "How to read this", "nodes_partial", "p99"}) {
    EXPECT_NE(html.find(needle), std::string::npos) << needle;
  }
  // The JSON keeps the text, with invalid UTF-8 replaced rather than refused.
  const auto json = nlohmann::json::parse(readFileBytes(dir / "summary.json"), nullptr, false);
  ASSERT_FALSE(json.is_discarded());
  EXPECT_EQ(json["run"]["path_file"], info.pathFile);
}

TEST(BenchReport, SingleFrameRunIsDrawable) {
  TempDir dir("bench_report_one");
  const auto frames = syntheticFrames(1);
  ASSERT_TRUE(writeBenchReport(dir.str(), runInfo(), frames, {}).ok());
  EXPECT_EQ(checkXml(readFileBytes(dir / "timeline.svg")).error, "");
  EXPECT_EQ(checkXml(readFileBytes(dir / "report.html")).error, "");
  EXPECT_EQ(lines(readFileBytes(dir / "frames.csv")).size(), 2U);
}

TEST(BenchReport, LongRunsAreDownsampledButKeepSpikes) {
  TempDir dir("bench_report_long");
  auto frames = syntheticFrames(60000);  // 1000 s at 60 Hz
  frames[31234].stats.frame_ms = 40.0;   // a lone spike must survive the min/max buckets
  ASSERT_TRUE(writeBenchReport(dir.str(), runInfo(), frames, {}).ok());
  const std::string svg = readFileBytes(dir / "timeline.svg");
  EXPECT_EQ(checkXml(svg).error, "");
  EXPECT_LT(svg.size(), 2'000'000U);
  EXPECT_EQ(lines(readFileBytes(dir / "frames.csv")).size(), frames.size() + 1);
}

TEST(BenchReport, SameInputsGiveIdenticalBytes) {
  TempDir a("bench_report_det_a");
  TempDir b("bench_report_det_b");
  const auto frames = syntheticFrames(900);
  const auto keysA = keyFramesIn(a, {0, 7});
  const auto keysB = keyFramesIn(b, {0, 7});
  ASSERT_TRUE(writeBenchReport(a.str(), runInfo(), frames, keysA).ok());
  ASSERT_TRUE(writeBenchReport(b.str(), runInfo(), frames, keysB).ok());
  for (const char* name : kReportFiles) {
    const std::string first = readFileBytes(a / name);
    EXPECT_FALSE(first.empty()) << name;
    EXPECT_EQ(first, readFileBytes(b / name)) << name;
  }
  // And again over the existing files.
  const std::string before = readFileBytes(a / "summary.json");
  ASSERT_TRUE(writeBenchReport(a.str(), runInfo(), frames, keysA).ok());
  EXPECT_EQ(readFileBytes(a / "summary.json"), before);
}

TEST(BenchReport, UnwritableDirectoryIsAnErrorAndWritesNothing) {
  TempDir dir("bench_report_unwritable");
  const auto frames = syntheticFrames(10);
  // Missing directory: not created.
  const std::string missing = (dir / "missing").string();
  Status s = writeBenchReport(missing, runInfo(), frames, {});
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().format().find(missing), std::string::npos) << s.error().format();
  EXPECT_FALSE(fs::exists(missing));
  // A "directory" that is a regular file (unwritable even for root).
  const std::string file = (dir / "plain_file").string();
  std::ofstream(file) << "x";
  s = writeBenchReport(file + "/out", runInfo(), frames, {});
  ASSERT_FALSE(s.ok());
  s = writeBenchReport(file, runInfo(), frames, {});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(readFileBytes(file), "x");
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.str())) ++count;
  EXPECT_EQ(count, 1U);
}

TEST(BenchReport, BadInputIsAnErrorAndWritesNothing) {
  TempDir dir("bench_report_bad");
  auto frames = syntheticFrames(10);
  const auto expectNothingWritten = [&](const Status& s, const std::string& fieldPart) {
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().format().find(fieldPart), std::string::npos) << s.error().format();
    EXPECT_TRUE(fs::is_empty(dir.str())) << s.error().format();
  };
  expectNothingWritten(writeBenchReport(dir.str(), runInfo(), {}, {}), "no frames");
  auto nan = frames;
  nan[3].stats.gpu_ms = std::nan("");
  expectNothingWritten(writeBenchReport(dir.str(), runInfo(), nan, {}), "frames[3].gpu_ms");
  auto backwards = frames;
  backwards[5].t_s = 0;
  expectNothingWritten(writeBenchReport(dir.str(), runInfo(), backwards, {}), "frames[5].t_s");
  const BenchKeyFrame missing[] = {{7.0, "frame_t7.png"}};
  expectNothingWritten(writeBenchReport(dir.str(), runInfo(), frames, missing), "frame_t7.png");
  const BenchKeyFrame outside[] = {{7.0, "../frame_t7.png"}};
  expectNothingWritten(writeBenchReport(dir.str(), runInfo(), frames, outside), "keyFrames[0].imageFile");
}

TEST(BenchReport, FailedWriteLeavesThePreviousReportIntact) {
  TempDir dir("bench_report_keep");
  const auto frames = syntheticFrames(20);
  ASSERT_TRUE(writeBenchReport(dir.str(), runInfo(), frames, {}).ok());
  std::map<std::string, std::string> before;
  for (const char* name : kReportFiles) before[name] = readFileBytes(dir / name);
  // Block the temporary of the third file with a directory: the first two temporaries are already
  // written by then and must not be renamed over the old report.
  const fs::path blocker = dir / (".timeline.svg.tmp" + std::to_string(::getpid()));
  fs::create_directories(blocker / "inside");
  auto changed = syntheticFrames(30);
  const Status s = writeBenchReport(dir.str(), runInfo(), changed, {});
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().format().find("timeline.svg"), std::string::npos) << s.error().format();
  for (const char* name : kReportFiles) EXPECT_EQ(readFileBytes(dir / name), before[name]) << name;
  EXPECT_FALSE(fs::exists(dir / (".frames.csv.tmp" + std::to_string(::getpid()))));
  EXPECT_FALSE(fs::exists(dir / (".summary.json.tmp" + std::to_string(::getpid()))));
}

TEST(BenchReport, MarkupEscaping) {
  EXPECT_EQ(escapeMarkup("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(escapeMarkup("tab\tok\x01"), "tab\tok?");
  EXPECT_EQ(escapeMarkup("\xc3\xa9"), "\xc3\xa9");  // é stays
  EXPECT_EQ(escapeMarkup("\xc3"), "?");             // truncated sequence
  EXPECT_EQ(escapeMarkup("\xed\xa0\x80"), "???");   // a surrogate
  EXPECT_EQ(escapeMarkup("\xc0\xaf"), "??");        // overlong '/'
  EXPECT_EQ(percentEncodePath("key frames/t 7&.png"), "key%20frames/t%207%26.png");
  EXPECT_EQ(formatFixed(-0.0, 2), "0.00");
  EXPECT_EQ(formatFixed(-0.0001, 2), "0.00");
  EXPECT_EQ(formatFixed(-1.5, 1), "-1.5");
  EXPECT_EQ(formatFixed(1234567.125, 3), "1234567.125");
}

}  // namespace
}  // namespace globe
