#include "planet/sources/raster_pyramid.h"

#include "planet/core/data_directory.h"

#include "planet/core/atomic_file.h"
#include "planet/core/hash.h"

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>

namespace globe {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'G', 'L', 'B', 'P', 'Y', 'R', '0', '1'};
constexpr std::size_t kHeaderBytes = 16;      // magic, uint32 level count, uint32 reserved
constexpr std::size_t kLevelEntryBytes = 16;  // int32 width, int32 height, double deviation bound

float nan() { return std::numeric_limits<float>::quiet_NaN(); }

// The cache file's name: the hash of the source's path, band, size and modification time, so an
// edited or replaced raster never reads a stale pyramid.
std::string cacheFileName(const std::string& path, int band) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  const std::uint64_t bytes = ec ? 0 : std::uint64_t(size);
  const auto time = fs::last_write_time(path, ec);
  const std::uint64_t stamp = ec ? 0 : std::uint64_t(time.time_since_epoch().count());
  std::uint64_t h = mix64(bytes) ^ mix64(stamp + 1);
  for (const char c : path) h = mix64(h ^ std::uint8_t(c));
  if (band != 1) h = mix64(h ^ std::uint64_t(band));  // band 1 keeps the name pyramids had before
  return fmt::format("{:016x}.pyramid", h);
}

// One coarser level: each pixel the mean of the valid pixels of its 2 x 2 block (no-data when
// fewer than two are valid), and the min/max of the level-0 values beneath it.
struct LevelValues {
  int width = 0, height = 0;
  std::vector<float> mean, min, max;
};

LevelValues halve(const LevelValues& fine, int width, int height) {
  LevelValues c{width, height, std::vector<float>(std::size_t(width) * std::size_t(height), nan()), {}, {}};
  c.min = c.mean;
  c.max = c.mean;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double sum = 0.0;
      int valid = 0;
      float lo = std::numeric_limits<float>::infinity(), hi = -lo;
      for (int k = 0; k < 4; ++k) {
        const int fx = 2 * x + (k & 1), fy = 2 * y + (k >> 1);
        if (fx >= fine.width || fy >= fine.height) continue;
        const std::size_t i = std::size_t(fy) * std::size_t(fine.width) + std::size_t(fx);
        if (std::isnan(fine.mean[i])) continue;
        sum += fine.mean[i];
        ++valid;
        lo = std::min(lo, fine.min[i]);
        hi = std::max(hi, fine.max[i]);
      }
      const std::size_t o = std::size_t(y) * std::size_t(width) + std::size_t(x);
      if (valid >= 2) c.mean[o] = float(sum / valid);
      if (valid >= 1) {
        c.min[o] = lo;
        c.max[o] = hi;
      }
    }
  }
  return c;
}

// How far a finer level's bilinear height can lie from this level's: a bilinear height is a
// convex combination of pixels whose level-0 values lie within the 3 x 3 neighbourhood's min/max.
double deviationBound(const LevelValues& l) {
  double bound = 0.0;
  for (int y = 0; y < l.height; ++y) {
    for (int x = 0; x < l.width; ++x) {
      const float v = l.mean[std::size_t(y) * std::size_t(l.width) + std::size_t(x)];
      if (std::isnan(v)) continue;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = std::clamp(x + dx, 0, l.width - 1), ny = std::clamp(y + dy, 0, l.height - 1);
          const std::size_t n = std::size_t(ny) * std::size_t(l.width) + std::size_t(nx);
          if (std::isnan(l.min[n])) continue;
          bound = std::max({bound, double(l.max[n]) - v, v - double(l.min[n])});
        }
      }
    }
  }
  return bound;
}

bool readAt(int fd, void* out, std::size_t bytes, std::uint64_t offset) {
  auto* p = static_cast<char*>(out);
  while (bytes > 0) {
    const ssize_t n = ::pread(fd, p, bytes, off_t(offset));
    if (n <= 0) return false;
    p += n;
    bytes -= std::size_t(n);
    offset += std::uint64_t(n);
  }
  return true;
}

}  // namespace

struct RasterPyramid::Built {
  int fd = -1;                        // the cache file, or -1: the levels stay in RAM
  std::string file;                   // its path
  std::vector<std::uint64_t> offset;  // per level, where its pixels start in the file
  std::vector<std::vector<float>> ram;
  ~Built() {
    if (fd >= 0) ::close(fd);
  }
};

int pyramidLevelFor(double pixel0_m, double spacing_m, int levelCount) {
  int k = 0;
  while (k + 1 < levelCount && pixel0_m * std::ldexp(1.0, k + 1) <= spacing_m) ++k;
  return k;
}

std::string sourceCacheDirectory() { return userCacheDirectory("GLOBE_SOURCE_CACHE_DIR", "sources"); }

RasterPyramid::RasterPyramid(const RasterFile& raster, std::string cacheDirectory)
    : raster_(raster), cacheDirectory_(std::move(cacheDirectory)) {
  const RasterFacts& f = raster.facts();
  levels_.push_back({f.width, f.height, 0.0});
  // Levels down to 2 x 2 pixels (bilinear needs them): the coarsest few are tiny, and the feather
  // beyond the border reads them (source_mosaic.cpp, readLayer).
  for (int k = 1; k < 30; ++k) {
    const int w = (f.width + (1 << k) - 1) >> k, h = (f.height + (1 << k) - 1) >> k;
    if (w < 2 || h < 2) break;
    levels_.push_back({w, h, 0.0});
  }
  // The file's own overviews serve when there is one for every level (GDAL rounds sizes either way).
  overview_.assign(levels_.size(), -1);
  const std::vector<std::pair<int, int>> sizes = raster.overviewSizes();
  bool all = true;
  for (std::size_t k = 1; k < levels_.size(); ++k) {
    const int w = f.width >> k, h = f.height >> k;
    for (std::size_t i = 0; i < sizes.size() && overview_[k] < 0; ++i) {
      const auto [ow, oh] = sizes[i];
      if ((ow == levels_[k].width || ow == w) && (oh == levels_[k].height || oh == h) && ow >= 2 && oh >= 2) {
        overview_[k] = int(i);
        levels_[k].width = ow;
        levels_[k].height = oh;
      }
    }
    all = all && overview_[k] >= 0;
  }
  if (!all) std::fill(overview_.begin() + 1, overview_.end(), -1);
  // Until a pyramid is built its bounds are the whole range (overview levels keep it: reading
  // every level-0 pixel to tighten it is what overviews are there to avoid).
  for (std::size_t k = 1; k < levels_.size(); ++k) levels_[k].deviationBound = f.max_value - f.min_value;
  if (all) built_ = true;
}

RasterPyramid::~RasterPyramid() = default;

PyramidLevel RasterPyramid::level(int k) const {
  if (k == 0 || built_.load(std::memory_order_acquire)) return levels_[std::size_t(k)];
  const PyramidLevel& l = levels_[std::size_t(k)];  // its bound may be being written: not read
  return {l.width, l.height, raster_.facts().max_value - raster_.facts().min_value};
}

std::string RasterPyramid::cacheFile() const {
  std::lock_guard lock(buildMutex_);
  return builtData_ ? builtData_->file : std::string();
}

Result<RasterBlock> RasterPyramid::readLevel(int k, int x0, int y0, int w, int h) const {
  if (k == 0) return raster_.read(x0, y0, w, h);
  if (overview_[std::size_t(k)] >= 0) return raster_.read(x0, y0, w, h, overview_[std::size_t(k)]);
  if (Status s = ensureBuilt(); !s) return s.error();
  return readBuilt(k, x0, y0, w, h);
}

Status RasterPyramid::ensureBuilt() const {
  if (built_.load(std::memory_order_acquire)) return Ok{};
  std::lock_guard lock(buildMutex_);
  if (built_.load(std::memory_order_relaxed)) return Ok{};
  const std::string file = (fs::path(cacheDirectory_) / cacheFileName(raster_.path(), raster_.band())).string();
  if (!loadCache(file)) {
    if (Status s = build(file); !s) return s;
  }
  built_.store(true, std::memory_order_release);
  return Ok{};
}

// A cache file written earlier for the same source: header, level sizes and length must match.
bool RasterPyramid::loadCache(const std::string& file) const {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  auto data = std::make_unique<Built>();
  data->fd = fd;
  data->file = file;
  const std::size_t n = levels_.size();
  std::vector<char> header(kHeaderBytes + kLevelEntryBytes * (n - 1));
  if (!readAt(fd, header.data(), header.size(), 0) || std::memcmp(header.data(), kMagic, 8) != 0) return false;
  std::uint32_t count = 0;
  std::memcpy(&count, header.data() + 8, 4);
  if (count != n) return false;
  std::vector<double> bounds(n, 0.0);
  std::uint64_t offset = header.size();
  data->offset.assign(n, 0);
  for (std::size_t k = 1; k < n; ++k) {
    std::int32_t wh[2];
    std::memcpy(wh, header.data() + kHeaderBytes + kLevelEntryBytes * (k - 1), 8);
    std::memcpy(&bounds[k], header.data() + kHeaderBytes + kLevelEntryBytes * (k - 1) + 8, 8);
    if (wh[0] != levels_[k].width || wh[1] != levels_[k].height || !std::isfinite(bounds[k])) return false;
    data->offset[k] = offset;
    offset += std::uint64_t(wh[0]) * std::uint64_t(wh[1]) * sizeof(float);
  }
  if (::lseek(fd, 0, SEEK_END) != off_t(offset)) return false;
  for (std::size_t k = 1; k < n; ++k) levels_[k].deviationBound = bounds[k];
  builtData_ = std::move(data);
  return true;
}

// Builds every level >= 1 from level 0 (read in strips of one tile row) and writes the cache file
// atomically; where it cannot be written the levels stay in RAM.
Status RasterPyramid::build(const std::string& file) const {
  const std::size_t n = levels_.size();
  std::vector<LevelValues> values(n);
  LevelValues& first = values[1];
  first = {levels_[1].width, levels_[1].height, {}, {}, {}};
  first.mean.assign(std::size_t(first.width) * std::size_t(first.height), nan());
  first.min = first.mean;
  first.max = first.mean;
  const int w0 = levels_[0].width, h0 = levels_[0].height;
  for (int y0 = 0; y0 < h0; y0 += kSourceTilePixels) {
    const int rows = std::min(kSourceTilePixels, h0 - y0);
    Result<RasterBlock> strip = raster_.read(0, y0, w0, rows);
    if (!strip) return strip.error();
    LevelValues fine{w0, rows, std::move(strip->values), {}, {}};
    fine.min = fine.mean;
    fine.max = fine.mean;
    const LevelValues half = halve(fine, first.width, (rows + 1) / 2);
    const std::size_t at = std::size_t(y0 / 2) * std::size_t(first.width);
    std::copy(half.mean.begin(), half.mean.end(), first.mean.begin() + std::ptrdiff_t(at));
    std::copy(half.min.begin(), half.min.end(), first.min.begin() + std::ptrdiff_t(at));
    std::copy(half.max.begin(), half.max.end(), first.max.begin() + std::ptrdiff_t(at));
  }
  for (std::size_t k = 2; k < n; ++k) values[k] = halve(values[k - 1], levels_[k].width, levels_[k].height);
  std::string content(kMagic, 8);
  const std::uint32_t count = std::uint32_t(n), reserved = 0;
  content.append(reinterpret_cast<const char*>(&count), 4).append(reinterpret_cast<const char*>(&reserved), 4);
  auto data = std::make_unique<Built>();
  data->offset.assign(n, 0);
  std::uint64_t offset = kHeaderBytes + kLevelEntryBytes * (n - 1);
  for (std::size_t k = 1; k < n; ++k) {
    levels_[k].deviationBound = deviationBound(values[k]);
    const std::int32_t wh[2] = {levels_[k].width, levels_[k].height};
    content.append(reinterpret_cast<const char*>(wh), 8)
        .append(reinterpret_cast<const char*>(&levels_[k].deviationBound), 8);
    data->offset[k] = offset;
    offset += values[k].mean.size() * sizeof(float);
  }
  for (std::size_t k = 1; k < n; ++k)
    content.append(reinterpret_cast<const char*>(values[k].mean.data()), values[k].mean.size() * sizeof(float));
  std::error_code ec;
  fs::create_directories(cacheDirectory_, ec);
  if (!ec && writeFileAtomically(file, content, "source pyramid").ok()) {
    data->fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    data->file = file;
  }
  if (data->fd < 0) {
    data->file.clear();
    data->ram.resize(n);
    for (std::size_t k = 1; k < n; ++k) data->ram[k] = std::move(values[k].mean);
  }
  builtData_ = std::move(data);
  return Ok{};
}

Result<RasterBlock> RasterPyramid::readBuilt(int k, int x0, int y0, int w, int h) const {
  const PyramidLevel& l = levels_[std::size_t(k)];
  if (x0 < 0 || y0 < 0 || w <= 0 || h <= 0 || x0 + w > l.width || y0 + h > l.height)
    return Error::inFile(raster_.path(), fmt::format("pyramid level {} has no pixels there", k));
  RasterBlock block{x0, y0, w, h, std::vector<float>(std::size_t(w) * std::size_t(h))};
  const Built& data = *builtData_;
  for (int r = 0; r < h; ++r) {
    const std::size_t first = std::size_t(y0 + r) * std::size_t(l.width) + std::size_t(x0);
    float* out = block.values.data() + std::size_t(r) * std::size_t(w);
    if (data.fd < 0) {
      std::copy_n(data.ram[std::size_t(k)].data() + first, w, out);
    } else if (!readAt(data.fd, out, std::size_t(w) * sizeof(float), data.offset[std::size_t(k)] + first * 4)) {
      return Error::inFile(data.file, "read failed (source pyramid cache)");
    }
  }
  return block;
}

}  // namespace globe
