// Checks screenshots written by `globe view` (and `globe render`) for the viewer tests.
//
//   viewer_screenshot_check coverage FILE WIDTH HEIGHT MIN MAX [MIN_GRID]
//       expected size, and the share of the picture the planet covers within [MIN, MAX] (so neither
//       all background nor all ground). EXR: pixels with a finite depth Z (terrain: the sky and
//       space are +inf). PNG: pixels that are not black (the sphere preview over black space).
//       MIN_GRID: a least share of grid-coloured pixels (the sphere mode's F1/L grid).
//   viewer_screenshot_check same A B        A and B hold the same colours (8-bit sRGB, +-1 level)
//   viewer_screenshot_check differ A B      more than 1% of the pixels differ by more than that
//   viewer_screenshot_check depth A B TOL   EXR depths agree: terrain in the same pixels (99.5%),
//                                           and relative difference <= TOL in 99% of them
//   viewer_screenshot_check pose PATHFILE   prints the last keyframe as LAT,LON,H,HEADING,PITCH,ROLL
//                                           (for globe render --at), after parsing the whole file
// Prints what it measured; exits 0 when the check passes, 1 when it fails, 2 on bad arguments.
#include "engine/io/image_io.h"
#include "planet/paths/camera_path_file.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

globe::Result<globe::ImageRgba> readImage(const std::string& path) {
  if (path.size() > 4 && path.substr(path.size() - 4) == ".exr") return globe::readExr(path);
  return globe::readImage8(path);
}

int usage(const char* argv0) {
  std::fprintf(stderr,
               "usage: %s coverage FILE W H MIN MAX [MIN_GRID] | same A B | differ A B | depth A B TOL | pose PATH\n",
               argv0);
  return 2;
}

int coverage(int argc, char** argv) {
  auto image = readImage(argv[2]);
  if (!image) {
    std::fprintf(stderr, "FAIL: %s\n", image.error().format().c_str());
    return 1;
  }
  unsigned long width = std::strtoul(argv[3], nullptr, 10), height = std::strtoul(argv[4], nullptr, 10);
  double minPlanet = std::atof(argv[5]), maxPlanet = std::atof(argv[6]);
  double minGrid = argc == 8 ? std::atof(argv[7]) : 0.0;
  if (image->width != width || image->height != height) {
    std::fprintf(stderr, "FAIL: %s is %ux%u, expected %lux%lu\n", argv[2], image->width, image->height, width, height);
    return 1;
  }
  size_t planet = 0, grid = 0, n = size_t(image->width) * image->height;
  bool depth = !image->z.empty();
  for (size_t i = 0; i < n; ++i) {
    const float* p = &image->rgba[i * 4];
    if (depth ? std::isfinite(image->z[i]) : (p[0] > 0.002f || p[1] > 0.002f || p[2] > 0.002f)) ++planet;
    // Grid lines are yellow or orange over blue-green ground: red clearly above blue.
    if (p[0] > 0.25f && p[0] > p[2] + 0.15f) ++grid;
  }
  double planetShare = double(planet) / double(n), gridShare = double(grid) / double(n);
  std::printf("%s: %ux%u, planet %.1f%% (%s), grid %.2f%%\n", argv[2], image->width, image->height, planetShare * 100,
              depth ? "finite depth" : "not black", gridShare * 100);
  bool ok = true;
  if (planetShare < minPlanet || planetShare > maxPlanet) {
    std::fprintf(stderr, "FAIL: planet covers %.1f%% of %s, expected [%.1f%%, %.1f%%]\n", planetShare * 100, argv[2],
                 minPlanet * 100, maxPlanet * 100);
    ok = false;
  }
  if (gridShare < minGrid) {
    std::fprintf(stderr, "FAIL: grid covers %.2f%% of %s, expected at least %.2f%%\n", gridShare * 100, argv[2],
                 minGrid * 100);
    ok = false;
  }
  return ok ? 0 : 1;
}

// Share of pixels whose 8-bit sRGB colour differs by more than one level in any channel.
int compare(const std::string& mode, const char* a, const char* b) {
  auto x = readImage(a), y = readImage(b);
  if (!x || !y) {
    std::fprintf(stderr, "FAIL: %s\n", (!x ? x.error() : y.error()).format().c_str());
    return 1;
  }
  if (x->width != y->width || x->height != y->height) {
    std::fprintf(stderr, "FAIL: %s is %ux%u but %s is %ux%u\n", a, x->width, x->height, b, y->width, y->height);
    return mode == "differ" ? 0 : 1;
  }
  size_t n = size_t(x->width) * x->height, differing = 0;
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      int p = globe::linearToSrgb8(x->rgba[i * 4 + size_t(c)]), q = globe::linearToSrgb8(y->rgba[i * 4 + size_t(c)]);
      if (std::abs(p - q) > 1) {
        ++differing;
        break;
      }
    }
  }
  double share = double(differing) / double(n);
  std::printf("%s vs %s: %.3f%% of the pixels differ\n", a, b, share * 100);
  bool ok = mode == "same" ? differing == 0 : share > 0.01;
  if (!ok) std::fprintf(stderr, "FAIL: expected %s images\n", mode == "same" ? "identical" : "different");
  return ok ? 0 : 1;
}

int depth(const char* a, const char* b, double tolerance) {
  auto x = globe::readExr(a), y = globe::readExr(b);
  if (!x || !y) {
    std::fprintf(stderr, "FAIL: %s\n", (!x ? x.error() : y.error()).format().c_str());
    return 1;
  }
  if (x->width != y->width || x->height != y->height || x->z.empty() || y->z.empty()) {
    std::fprintf(stderr, "FAIL: %s and %s differ in size or lack depth\n", a, b);
    return 1;
  }
  size_t n = x->z.size(), sameCoverage = 0, terrain = 0, close = 0;
  for (size_t i = 0; i < n; ++i) {
    bool fx = std::isfinite(x->z[i]), fy = std::isfinite(y->z[i]);
    if (fx == fy) ++sameCoverage;
    if (fx && fy) {
      ++terrain;
      if (std::abs(x->z[i] - y->z[i]) <= tolerance * std::max(std::abs(x->z[i]), std::abs(y->z[i]))) ++close;
    }
  }
  double coverageShare = double(sameCoverage) / double(n);
  double closeShare = terrain ? double(close) / double(terrain) : 0.0;
  std::printf("%s vs %s: terrain in the same pixels %.2f%%, depth within %g in %.2f%% of %zu terrain pixels\n", a, b,
              coverageShare * 100, tolerance, closeShare * 100, terrain);
  bool ok = coverageShare >= 0.995 && closeShare >= 0.99 && terrain > 0;
  if (!ok) std::fprintf(stderr, "FAIL: depth images do not match\n");
  return ok ? 0 : 1;
}

int pose(const char* file) {
  auto path = globe::loadCameraPath(file);
  if (!path) {
    std::fprintf(stderr, "FAIL: %s\n", path.error().format().c_str());
    return 1;
  }
  const globe::GeodeticPose& p = path->keyframes().back().pose;
  std::printf("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", p.latitude_deg, p.longitude_deg, p.height_m, p.heading_deg,
              p.pitch_deg, p.roll_deg);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage(argv[0]);
  std::string mode = argv[1];
  if (mode == "coverage" && (argc == 7 || argc == 8)) return coverage(argc, argv);
  if ((mode == "same" || mode == "differ") && argc == 4) return compare(mode, argv[2], argv[3]);
  if (mode == "depth" && argc == 5) return depth(argv[2], argv[3], std::atof(argv[4]));
  if (mode == "pose" && argc == 3) return pose(argv[2]);
  return usage(argv[0]);
}
