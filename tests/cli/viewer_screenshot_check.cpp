// Checks a screenshot written by `globe view`: the expected size, the planet covering a share of
// the picture within [min, max] (so neither all space nor all ground: the camera is above the
// planet and looking at it), and optionally a share of grid-coloured pixels (the F1/L debug view).
// Usage: viewer_screenshot_check FILE WIDTH HEIGHT MIN_PLANET MAX_PLANET [MIN_GRID]
// Prints what it measured; exits 0 when every check passes, 1 otherwise, 2 on bad arguments.
#include "engine/image_io.h"

#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  if (argc != 6 && argc != 7) {
    std::fprintf(stderr, "usage: %s FILE WIDTH HEIGHT MIN_PLANET MAX_PLANET [MIN_GRID]\n", argv[0]);
    return 2;
  }
  auto image = globe::readPng(argv[1]);
  if (!image) {
    std::fprintf(stderr, "FAIL: %s\n", image.error().format().c_str());
    return 1;
  }
  unsigned long width = std::strtoul(argv[2], nullptr, 10), height = std::strtoul(argv[3], nullptr, 10);
  double minPlanet = std::atof(argv[4]), maxPlanet = std::atof(argv[5]);
  double minGrid = argc == 7 ? std::atof(argv[6]) : 0.0;
  if (image->width != width || image->height != height) {
    std::fprintf(stderr, "FAIL: %s is %ux%u, expected %lux%lu\n", argv[1], image->width, image->height, width, height);
    return 1;
  }
  size_t planet = 0, grid = 0, n = size_t(image->width) * image->height;
  for (size_t i = 0; i < n; ++i) {
    const float* p = &image->rgba[i * 4];
    // Space is cleared to exact black; the sphere preview's darkest shade (ambient) is not.
    if (p[0] > 0.002f || p[1] > 0.002f || p[2] > 0.002f) ++planet;
    // Grid lines are yellow or orange over blue-green ground: red clearly above blue.
    if (p[0] > 0.25f && p[0] > p[2] + 0.15f) ++grid;
  }
  double planetShare = double(planet) / double(n), gridShare = double(grid) / double(n);
  std::printf("%s: %ux%u, planet %.1f%%, grid %.2f%%\n", argv[1], image->width, image->height, planetShare * 100,
              gridShare * 100);
  bool ok = true;
  if (planetShare < minPlanet || planetShare > maxPlanet) {
    std::fprintf(stderr, "FAIL: planet covers %.1f%% of %s, expected [%.1f%%, %.1f%%]\n", planetShare * 100, argv[1],
                 minPlanet * 100, maxPlanet * 100);
    ok = false;
  }
  if (gridShare < minGrid) {
    std::fprintf(stderr, "FAIL: grid covers %.2f%% of %s, expected at least %.2f%%\n", gridShare * 100, argv[1],
                 minGrid * 100);
    ok = false;
  }
  return ok ? 0 : 1;
}
