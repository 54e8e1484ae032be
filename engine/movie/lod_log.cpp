#include "engine/movie/lod_log.h"

#include "planet/core/input_file.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace globe {

namespace {

constexpr std::size_t kLevels = kMaxNodeLevel + 1;
constexpr const char* kHeader =
    "# globe movie: what the LOD ranges had learned after each frame (frame, then per level the largest "
    "node diagonal, payload error and calibrated error seen, in metres as hexadecimal floats); "
    "a resumed movie restores it (docs/camera-paths.md)\n";

// One line: the frame, then 3 * kLevels numbers. Anything else (a line cut short) is nullopt.
std::optional<std::pair<uint64_t, LodRanges::Observations>> parseLine(const std::string& line) {
  std::istringstream in(line);
  std::string token;
  if (!(in >> token)) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const unsigned long long frame = std::strtoull(token.c_str(), &end, 10);
  if (errno || *end || token.empty() || token[0] == '-') return std::nullopt;
  LodRanges::Observations o;
  for (auto* values : {&o.maxDiagonal, &o.maxError, &o.maxCalibrated})
    for (double& v : *values) {
      if (!(in >> token)) return std::nullopt;
      v = std::strtod(token.c_str(), &end);
      if (*end) return std::nullopt;
    }
  if (in >> token) return std::nullopt;
  return std::make_pair(uint64_t(frame), o);
}

}  // namespace

Result<LodLog> LodLog::open(const std::string& directory) {
  LodLog log;
  log.file_ = (std::filesystem::path(directory) / kLodLogName).string();
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(log.file_, ec))) return log;
  // A movie of 1e6 frames logs ~2 KiB each: far past any sequence on disk, the bound is a guard.
  Result<std::string> text = readInputFile(log.file_, "movie LOD log", std::size_t{4} << 30);
  if (!text) return text.error();
  std::size_t start = 0;
  while (start < text->size()) {
    const std::size_t newline = text->find('\n', start);
    if (newline == std::string::npos) {  // the last line, cut short by a kill: the next entry starts anew
      log.cutShort_ = true;
      break;
    }
    const std::string line = text->substr(start, newline - start);
    start = newline + 1;
    if (line.empty() || line[0] == '#') continue;
    if (auto entry = parseLine(line)) log.entries_.insert(*entry);
  }
  return log;
}

const LodRanges::Observations* LodLog::after(uint64_t frame) const {
  auto it = entries_.find(frame);
  return it == entries_.end() ? nullptr : &it->second;
}

std::optional<uint64_t> LodLog::latestBefore(uint64_t frame) const {
  auto it = entries_.lower_bound(frame);
  if (it == entries_.begin()) return std::nullopt;
  return std::prev(it)->first;
}

Status LodLog::record(uint64_t frame, const LodRanges::Observations& state) {
  if (entries_.count(frame)) return Ok{};
  std::error_code ec;
  const bool fresh = !std::filesystem::exists(file_, ec);
  std::string line = fresh ? kHeader : cutShort_ ? "\n" : "";
  line += fmt::format("{}", frame);
  for (const auto* values : {&state.maxDiagonal, &state.maxError, &state.maxCalibrated})
    for (double v : *values) line += fmt::format(" {:a}", v);
  line += '\n';
  std::ofstream out(file_, std::ios::app | std::ios::binary);
  out << line;
  out.flush();
  if (!out) return Error::inFileField(file_, "--out", "cannot append to the movie's LOD log");
  entries_.emplace(frame, state);
  cutShort_ = false;
  return Ok{};
}

}  // namespace globe
