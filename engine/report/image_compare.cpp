#include "engine/report/image_compare.h"

#include "planet/core/srgb.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>
#include <vector>

namespace globe {

namespace {

double labF(double t) {
  constexpr double kDelta = 6.0 / 29.0;
  return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
double cosDeg(double d) { return std::cos(d * std::numbers::pi / 180.0); }

glm::dvec3 pixel(const ImageView& image, size_t i) {
  return {image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]};
}

// Hue angle in degrees [0, 360); 0 for a grey.
double hueDeg(double b, double a) {
  if (a == 0.0 && b == 0.0) return 0.0;
  double h = degrees(std::atan2(b, a));
  return h < 0.0 ? h + 360.0 : h;
}

// The display-encoded luma Y' of every pixel.
std::vector<double> displayLuma(const ImageView& image) {
  std::vector<double> y(size_t(image.width) * image.height);
  for (size_t i = 0; i < y.size(); ++i) {
    glm::dvec3 c = pixel(image, i);
    y[i] = 0.2126 * srgbEncode(c.x) + 0.7152 * srgbEncode(c.y) + 0.0722 * srgbEncode(c.z);
  }
  return y;
}

constexpr int kSsimRadius = 5;  // 11 x 11 windows

// The Gaussian-weighted local means of `v` (w x h) over the windows that fit in the image, as a
// (w - 10) x (h - 10) image: separable, rows then columns.
std::vector<double> windowMeans(const std::vector<double>& v, int w, int h) {
  std::array<double, 2 * kSsimRadius + 1> g{};
  double sum = 0.0;
  for (int k = -kSsimRadius; k <= kSsimRadius; ++k) sum += g[k + kSsimRadius] = std::exp(-k * k / (2.0 * 1.5 * 1.5));
  for (double& x : g) x /= sum;
  int ow = w - 2 * kSsimRadius, oh = h - 2 * kSsimRadius;
  std::vector<double> rows(size_t(ow) * h), out(size_t(ow) * oh);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k < 2 * kSsimRadius + 1; ++k) s += g[k] * v[size_t(y) * w + x + k];
      rows[size_t(y) * ow + x] = s;
    }
  for (int y = 0; y < oh; ++y)
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k < 2 * kSsimRadius + 1; ++k) s += g[k] * rows[size_t(y + k) * ow + x];
      out[size_t(y) * ow + x] = s;
    }
  return out;
}

// The planet's disc in a render: the centre and radius (pixels) of the box around non-space pixels.
glm::dvec3 planetDisc(const ImageView& image) {
  double x0 = image.width, y0 = image.height, x1 = -1.0, y1 = -1.0;
  for (uint32_t row = 0; row < image.height; ++row)
    for (uint32_t col = 0; col < image.width; ++col)
      if (classifyEarthPixel(linearSrgbToLab(pixel(image, size_t(row) * image.width + col))) != EarthClass::kSpace) {
        x0 = std::min(x0, double(col)), x1 = std::max(x1, col + 1.0);
        y0 = std::min(y0, double(row)), y1 = std::max(y1, row + 1.0);
      }
  return {0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * std::max(x1 - x0, y1 - y0)};
}

glm::dvec3 meanLab(const ImageView& image) {
  glm::dvec3 sum(0.0);
  size_t n = size_t(image.width) * image.height;
  for (size_t i = 0; i < n; ++i) sum += linearSrgbToLab(pixel(image, i));
  return n ? sum / double(n) : sum;
}

}  // namespace

glm::dvec3 linearSrgbToLab(glm::dvec3 c) {
  c = glm::clamp(c, 0.0, 1.0);
  // sRGB primaries to XYZ, relative to the D65 white (0.95047, 1, 1.08883).
  double x = (0.4124564 * c.x + 0.3575761 * c.y + 0.1804375 * c.z) / 0.95047;
  double y = 0.2126729 * c.x + 0.7151522 * c.y + 0.0721750 * c.z;
  double z = (0.0193339 * c.x + 0.1191920 * c.y + 0.9503041 * c.z) / 1.08883;
  double fx = labF(x), fy = labF(y), fz = labF(z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// Sharma, Wu & Dalal (2005), equations 1-22.
double deltaE2000(glm::dvec3 lab1, glm::dvec3 lab2) {
  double cBar = 0.5 * (std::hypot(lab1.y, lab1.z) + std::hypot(lab2.y, lab2.z));
  double c7 = std::pow(cBar, 7.0), k7 = std::pow(25.0, 7.0);
  double g = 0.5 * (1.0 - std::sqrt(c7 / (c7 + k7)));
  double a1 = (1.0 + g) * lab1.y, a2 = (1.0 + g) * lab2.y;
  double c1 = std::hypot(a1, lab1.z), c2 = std::hypot(a2, lab2.z);
  double h1 = hueDeg(lab1.z, a1), h2 = hueDeg(lab2.z, a2);
  double dh = c1 * c2 == 0.0 ? 0.0 : h2 - h1;
  if (dh > 180.0) dh -= 360.0;
  if (dh < -180.0) dh += 360.0;
  double dL = lab2.x - lab1.x, dC = c2 - c1;
  double dH = 2.0 * std::sqrt(c1 * c2) * std::sin(dh * std::numbers::pi / 360.0);
  double lBar = 0.5 * (lab1.x + lab2.x), cBarP = 0.5 * (c1 + c2);
  double hBar = h1 + h2;
  if (c1 * c2 != 0.0)
    hBar = std::abs(h1 - h2) <= 180.0 ? 0.5 * hBar : (hBar < 360.0 ? 0.5 * (hBar + 360.0) : 0.5 * (hBar - 360.0));
  double t = 1.0 - 0.17 * cosDeg(hBar - 30.0) + 0.24 * cosDeg(2.0 * hBar) + 0.32 * cosDeg(3.0 * hBar + 6.0) -
             0.20 * cosDeg(4.0 * hBar - 63.0);
  double dTheta = 30.0 * std::exp(-std::pow((hBar - 275.0) / 25.0, 2.0));
  double cp7 = std::pow(cBarP, 7.0);
  double rC = 2.0 * std::sqrt(cp7 / (cp7 + k7));
  double l50 = (lBar - 50.0) * (lBar - 50.0);
  double sL = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50), sC = 1.0 + 0.045 * cBarP, sH = 1.0 + 0.015 * cBarP * t;
  double rT = -std::sin(2.0 * dTheta * std::numbers::pi / 180.0) * rC;
  double l = dL / sL, c = dC / sC, h = dH / sH;
  return std::sqrt(std::max(l * l + c * c + h * h + rT * c * h, 0.0));
}

double ssimLuminance(const ImageView& image, const ImageView& reference) {
  assert(image.width == reference.width && image.height == reference.height);
  int w = int(image.width), h = int(image.height);
  if (w <= 2 * kSsimRadius || h <= 2 * kSsimRadius) return 1.0;
  std::vector<double> x = displayLuma(image), y = displayLuma(reference);
  std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
  for (size_t i = 0; i < x.size(); ++i) xx[i] = x[i] * x[i], yy[i] = y[i] * y[i], xy[i] = x[i] * y[i];
  std::vector<double> mx = windowMeans(x, w, h), my = windowMeans(y, w, h);
  std::vector<double> sxx = windowMeans(xx, w, h), syy = windowMeans(yy, w, h), sxy = windowMeans(xy, w, h);
  constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;
  double sum = 0.0;
  for (size_t i = 0; i < mx.size(); ++i) {
    double vx = sxx[i] - mx[i] * mx[i], vy = syy[i] - my[i] * my[i], cxy = sxy[i] - mx[i] * my[i];
    sum += (2.0 * mx[i] * my[i] + kC1) * (2.0 * cxy + kC2) / ((mx[i] * mx[i] + my[i] * my[i] + kC1) * (vx + vy + kC2));
  }
  return sum / double(mx.size());
}

double meanColourDifference(const ImageView& image, const ImageView& reference) {
  return deltaE2000(meanLab(image), meanLab(reference));
}

EarthClass classifyEarthPixel(glm::dvec3 lab) {
  double chroma = std::hypot(lab.y, lab.z);
  if (lab.x < 3.0 && chroma < 5.0) return EarthClass::kSpace;
  // Blue to cyan hues (b* < 0 and not magenta): open and shallow water.
  if (lab.z < -5.0 && lab.y < -lab.z) return EarthClass::kSea;
  if (lab.x > 70.0 && chroma < 12.0) return EarthClass::kBright;
  return EarthClass::kLand;
}

EarthColours earthColours(const ImageView& image, bool equirectangular) {
  struct Sums {
    double weight = 0.0;
    glm::dvec3 lab{0.0}, square{0.0};
  } land, sea;
  const glm::dvec3 disc = equirectangular ? glm::dvec3(0.0) : planetDisc(image);
  for (uint32_t row = 0; row < image.height; ++row) {
    double latitude = (0.5 - (row + 0.5) / image.height) * std::numbers::pi;
    double weight = equirectangular ? std::cos(latitude) : 1.0;
    for (uint32_t col = 0; col < image.width; ++col) {
      if (!equirectangular && std::hypot(col + 0.5 - disc.x, row + 0.5 - disc.y) > 0.8 * disc.z) continue;
      glm::dvec3 lab = linearSrgbToLab(pixel(image, size_t(row) * image.width + col));
      EarthClass kind = classifyEarthPixel(lab);
      if (kind != EarthClass::kLand && kind != EarthClass::kSea) continue;
      Sums& s = kind == EarthClass::kLand ? land : sea;
      s.weight += weight;
      s.lab += weight * lab;
      s.square += weight * lab * lab;
    }
  }
  EarthColours out;
  if (land.weight > 0.0) {
    out.landLab = land.lab / land.weight;
    glm::dvec3 variance = land.square / land.weight - out.landLab * out.landLab;
    out.landSpread = std::sqrt(std::max(variance.x + variance.y + variance.z, 0.0));
  }
  if (sea.weight > 0.0) out.seaLab = sea.lab / sea.weight;
  double total = land.weight + sea.weight;
  out.landShare = total > 0.0 ? land.weight / total : 0.0;
  return out;
}

EarthComparison compareEarthColours(const EarthColours& image, const EarthColours& reference) {
  EarthComparison c;
  c.landDeltaE = deltaE2000(image.landLab, reference.landLab);
  c.seaDeltaE = deltaE2000(image.seaLab, reference.seaLab);
  c.spreadRatio = reference.landSpread > 0.0 ? image.landSpread / reference.landSpread : 0.0;
  return c;
}

}  // namespace globe
