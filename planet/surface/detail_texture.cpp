#include "planet/surface/detail_texture.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <numbers>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "planet/core/gradient_noise.h"
#include "planet/core/hash.h"
#include "planet/core/parallel_for.h"

namespace globe {

namespace {

// The grain: 6 octaves from 4 cells across the tile to 128 (2 texels a cell at 256^2), each 0.6
// times the amplitude of the one before (more fine grain than fBm's usual 0.5: this is detail seen
// from a few metres). Every period divides the size, so every octave tiles.
constexpr uint32_t kBasePeriod = 4;
constexpr int kOctaves = 6;
constexpr float kGain = 0.6f;
// The hue variation: a smoother noise per channel (periods 4 to 16), added at a fifth
// of the grain's weight, so a class's texture drifts slightly in hue without a second colour of its own.
constexpr uint32_t kHueBasePeriod = 4;
constexpr int kHueOctaves = 3;
constexpr float kHueWeight = 0.2f;
// The grain is read through a smooth periodic warp of up to ~kWarp tiles: lattice noise alone
// lines its features up with the lattice's axes.
constexpr uint32_t kWarpBasePeriod = 4;
constexpr int kWarpOctaves = 1;
constexpr float kWarp = 0.02f;
// Rec. 709 luminance of linear RGB: the alpha channel.
constexpr std::array<float, 3> kLuma{0.2126f, 0.7152f, 0.0722f};

// floor as an integer without libm's floorf, a call on x86-64 without SSE4.1 (the hot loop's cost).
int32_t floorToInt(float v) {
  const auto i = int32_t(v);
  return float(i) > v ? i - 1 : i;
}

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

// One octave of 2-D gradient noise [Perlin 2002] on a period x period lattice that wraps around, so
// the noise repeats every tile (1 unit) without a seam: unit gradients at random angles, tabulated
// (at most 128^2) rather than hashed per texel, and the lattice shifted by a random fraction of a
// cell per octave (gradient noise is 0 at lattice points: coinciding lattices would show as a grid).
class PeriodicLattice {
 public:
  PeriodicLattice(uint32_t period, uint32_t seed) : period_(period), gradients_(size_t(period) * period) {
    assert(std::has_single_bit(period));
    for (uint32_t i = 0; i < gradients_.size(); ++i) {
      const float angle = float(hashMix32(i ^ hashMix32(seed))) * (2.0f * std::numbers::pi_v<float> / 4294967296.0f);
      gradients_[i] = glm::vec2(std::cos(angle), std::sin(angle));
    }
    shift_ = glm::vec2(float(hashMix32(seed ^ 0x78U) >> 8), float(hashMix32(seed ^ 0x79U) >> 8)) / 16777216.0f;
  }

  // The noise at `p` in tile units (any value), times sqrt 2: roughly within [-1, 1].
  float operator()(glm::vec2 p) const {
    const glm::vec2 q = p * float(period_) + shift_;
    const int32_t cx = floorToInt(q.x), cy = floorToInt(q.y);
    const glm::vec2 d = q - glm::vec2(float(cx), float(cy));
    // The corners' indices modulo the period (a power of two: a mask, right for negatives too).
    const uint32_t mask = period_ - 1;
    const uint32_t x0 = uint32_t(cx) & mask, y0 = uint32_t(cy) & mask;
    const uint32_t x1 = (x0 + 1) & mask, y1 = (y0 + 1) & mask;
    const float n00 = glm::dot(at(x0, y0), d), n10 = glm::dot(at(x1, y0), d - glm::vec2(1.0f, 0.0f));
    const float n01 = glm::dot(at(x0, y1), d - glm::vec2(0.0f, 1.0f)), n11 = glm::dot(at(x1, y1), d - 1.0f);
    const float sx = fade(d.x), sy = fade(d.y);
    const float top = n00 + sx * (n10 - n00), bottom = n01 + sx * (n11 - n01);
    return std::numbers::sqrt2_v<float> * (top + sy * (bottom - top));
  }

 private:
  glm::vec2 at(uint32_t x, uint32_t y) const { return gradients_[size_t(y) * period_ + x]; }

  uint32_t period_;
  std::vector<glm::vec2> gradients_;
  glm::vec2 shift_{0.0f};
};

// fBm at `positions` (tile units); octaves finer than `maxPeriod` cells a tile (the texels) are
// left out.
std::vector<float> periodicFbm(std::span<const glm::vec2> positions, uint32_t maxPeriod, uint32_t basePeriod,
                               int octaves, uint32_t seed) {
  std::vector<float> field(positions.size(), 0.0f);
  float amplitude = 1.0f;
  uint32_t period = basePeriod;
  for (int o = 0; o < octaves && period <= maxPeriod; ++o, period *= 2, amplitude *= kGain) {
    const PeriodicLattice noise(period, hashMix32(seed + uint32_t(o) * 0x9e3779b9U));
    for (size_t i = 0; i < positions.size(); ++i) field[i] += amplitude * noise(positions[i]);
  }
  return field;
}

// The texel centres of a size x size tile, in tile units.
std::vector<glm::vec2> texelCentres(uint32_t size) {
  std::vector<glm::vec2> centres(size_t(size) * size);
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x)
      centres[size_t(y) * size + x] = (glm::vec2(float(x), float(y)) + 0.5f) / float(size);
  return centres;
}

// The centres moved by the periodic warp (so the warped tile still repeats seamlessly).
std::vector<glm::vec2> warped(const std::vector<glm::vec2>& centres, uint32_t size, uint32_t seed) {
  const std::vector<float> wx = periodicFbm(centres, size, kWarpBasePeriod, kWarpOctaves, hashMix32(seed ^ 0x5758U));
  const std::vector<float> wy = periodicFbm(centres, size, kWarpBasePeriod, kWarpOctaves, hashMix32(seed ^ 0x5759U));
  std::vector<glm::vec2> moved(centres.size());
  for (size_t i = 0; i < centres.size(); ++i) moved[i] = centres[i] + kWarp * glm::vec2(wx[i], wy[i]);
  return moved;
}

// Each class its own seed, apart from the planet's other seeds ("detail" in ASCII mixed in).
uint32_t layerSeed(std::uint64_t planetSeed, uint32_t layer) {
  return uint32_t(mix64(planetSeed ^ mix64(0x64657461696cULL + layer)) >> 32);
}

uint8_t toByte(float v) { return uint8_t(std::floor(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f)); }

// Writes one RGBA layer from three modulation fields already at mean 0.5 per channel.
void writeLayer(const std::array<std::vector<float>, 3>& rgb, std::span<std::uint8_t> out) {
  for (size_t i = 0; i < rgb[0].size(); ++i) {
    float luma = 0.0f;
    for (int c = 0; c < 3; ++c) {
      out[4 * i + size_t(c)] = toByte(rgb[size_t(c)][i]);
      luma += kLuma[size_t(c)] * rgb[size_t(c)][i];
    }
    out[4 * i + 3] = toByte(luma);
  }
}

double meanOf(const std::vector<float>& v) {
  double sum = 0.0;
  for (float x : v) sum += x;
  return v.empty() ? 0.0 : sum / double(v.size());
}

// One procedural layer: grain plus hue per channel, each channel moved to mean 0.5 and all three
// scaled alike (keeping their relative hue) so the largest excursion is contrast * 0.5. A linear
// map, not a clamp: the mean stays exactly 0.5 and every value within [0, 1].
void proceduralLayer(uint32_t size, uint32_t seed, double contrast, std::span<std::uint8_t> out) {
  const std::vector<glm::vec2> centres = texelCentres(size);
  const std::vector<float> grain = periodicFbm(warped(centres, size, seed), size, kBasePeriod, kOctaves, seed);
  std::array<std::vector<float>, 3> rgb;
  float largest = 0.0f;
  for (uint32_t c = 0; c < 3; ++c) {
    const std::vector<float> hue = periodicFbm(centres, size, kHueBasePeriod, kHueOctaves, hashMix32(seed ^ (c + 1)));
    std::vector<float>& channel = rgb[c];
    channel.resize(grain.size());
    for (size_t i = 0; i < grain.size(); ++i) channel[i] = grain[i] + kHueWeight * hue[i];
    const auto mean = float(meanOf(channel));
    for (float& v : channel) {
      v -= mean;
      largest = std::max(largest, std::abs(v));
    }
  }
  const float amplitude = largest > 0.0f ? float(std::clamp(contrast, 0.0, 1.0)) * 0.5f / largest : 0.0f;
  for (std::vector<float>& channel : rgb)
    for (float& v : channel) v = 0.5f + amplitude * v;
  writeLayer(rgb, out);
}

size_t layerBytes(uint32_t size) { return size_t(size) * size * 4; }

// Which source texels, with which weights, make destination texel d when resampling n texels to
// `size` along one axis: the covered interval's area when shrinking, the two neighbours (wrapping
// around: the image tiles) when growing.
struct Tap {
  uint32_t index;
  float weight;
};
std::vector<std::vector<Tap>> resampleTaps(uint32_t n, uint32_t size) {
  std::vector<std::vector<Tap>> taps(size);
  const double scale = double(n) / double(size);
  for (uint32_t d = 0; d < size; ++d) {
    if (n >= size) {
      const double lo = d * scale, hi = (d + 1) * scale;
      for (auto i = uint32_t(std::floor(lo)); i < std::min<double>(std::ceil(hi), n); ++i) {
        const double overlap = std::min(hi, i + 1.0) - std::max(lo, double(i));
        if (overlap > 0.0) taps[d].push_back({i, float(overlap / scale)});
      }
    } else {
      const double p = (d + 0.5) * scale - 0.5, i0 = std::floor(p);
      const auto f = float(p - i0);
      const auto wrap = [n](double i) { return uint32_t((int64_t(i) % int64_t(n) + n) % n); };
      taps[d] = {{wrap(i0), 1.0f - f}, {wrap(i0 + 1.0), f}};
    }
  }
  return taps;
}

// The image resampled to size x size, RGB only (3 fields), separably: rows, then columns.
std::array<std::vector<float>, 3> resampleRgb(uint32_t width, uint32_t height, std::span<const float> rgba,
                                              uint32_t size) {
  const auto tapsX = resampleTaps(width, size), tapsY = resampleTaps(height, size);
  std::vector<float> rows(size_t(height) * size * 3, 0.0f);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < size; ++x)
      for (const Tap& t : tapsX[x])
        for (size_t c = 0; c < 3; ++c)
          rows[(size_t(y) * size + x) * 3 + c] += t.weight * rgba[(size_t(y) * width + t.index) * 4 + c];
  std::array<std::vector<float>, 3> rgb;
  for (auto& channel : rgb) channel.assign(size_t(size) * size, 0.0f);
  for (uint32_t y = 0; y < size; ++y)
    for (const Tap& t : tapsY[y])
      for (uint32_t x = 0; x < size; ++x)
        for (size_t c = 0; c < 3; ++c)
          rgb[c][size_t(y) * size + x] += t.weight * rows[(size_t(t.index) * size + x) * 3 + c];
  return rgb;
}

}  // namespace

DetailTextureSet proceduralDetailTextures(const LandCover& cover, std::uint64_t planetSeed, uint32_t size) {
  assert(std::has_single_bit(size));
  DetailTextureSet set;
  set.size = size;
  set.layers = std::max<uint32_t>(1, uint32_t(cover.classes.size()));
  set.mips.assign(1, std::vector<std::uint8_t>(layerBytes(size) * set.layers));
  // Layers are independent: one per thread (8 layers at 256^2 take ~75 ms on one core).
  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, set.layers);
  parallelFor(set.layers, 1, threads, [&](size_t begin, size_t end) {
    for (size_t layer = begin; layer < end; ++layer) {
      const double contrast = layer < cover.classes.size() ? cover.classes[layer].detail_contrast : 0.0;
      const std::span<std::uint8_t> out(set.mips[0].data() + layer * layerBytes(size), layerBytes(size));
      proceduralLayer(size, layerSeed(planetSeed, uint32_t(layer)), contrast, out);
    }
  });
  buildDetailMips(set);
  return set;
}

void setDetailLayerFromImage(DetailTextureSet& set, uint32_t layer, uint32_t width, uint32_t height,
                             std::span<const float> linearRgba) {
  assert(layer < set.layers && width > 0 && height > 0 && linearRgba.size() == size_t(width) * height * 4);
  assert(!set.mips.empty() && set.mips[0].size() == layerBytes(set.size) * set.layers);
  std::array<std::vector<float>, 3> rgb = resampleRgb(width, height, linearRgba, set.size);
  for (std::vector<float>& channel : rgb) {
    const double mean = meanOf(channel);
    // A black channel has no pattern to keep: flat, so the class colour alone sets it.
    const float scale = mean > 1e-6 ? float(0.5 / mean) : 0.0f;
    for (float& v : channel) v = mean > 1e-6 ? std::min(v * scale, 1.0f) : 0.5f;
  }
  writeLayer(rgb, std::span(set.mips[0]).subspan(layer * layerBytes(set.size), layerBytes(set.size)));
}

void buildDetailMips(DetailTextureSet& set) {
  assert(std::has_single_bit(set.size) && !set.mips.empty());
  set.mips.resize(size_t(std::countr_zero(set.size)) + 1);
  std::vector<float> level(set.mips[0].begin(), set.mips[0].end());
  for (size_t m = 1; m < set.mips.size(); ++m) {
    const uint32_t n = set.size >> (m - 1), half = n / 2;
    std::vector<float> next(size_t(half) * half * 4 * set.layers);
    for (uint32_t layer = 0; layer < set.layers; ++layer) {
      const float* src = level.data() + size_t(layer) * n * n * 4;
      float* dst = next.data() + size_t(layer) * half * half * 4;
      for (uint32_t y = 0; y < half; ++y)
        for (uint32_t x = 0; x < half; ++x)
          for (size_t c = 0; c < 4; ++c) {
            const size_t a = (size_t(2 * y) * n + 2 * x) * 4 + c, b = a + size_t(n) * 4;
            dst[(size_t(y) * half + x) * 4 + c] = 0.25f * (src[a] + src[a + 4] + src[b] + src[b + 4]);
          }
    }
    set.mips[m].resize(next.size());
    // Level 0 holds bytes (0..255): round each level once, from the unrounded level above.
    for (size_t i = 0; i < next.size(); ++i) set.mips[m][i] = uint8_t(std::floor(next[i] + 0.5f));
    level = std::move(next);
  }
}

}  // namespace globe
