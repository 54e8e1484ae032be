// globe planet sample: the elevation that is drawn at points, one line "LAT,LON HEIGHT_M" each, or
// "LAT,LON nodata" inside a kept hole of a source (nodata = "hole", docs/elevation-data.md).
#include "commands.h"
#include "options.h"
#include "planet/camera/camera.h"
#include "planet/model/elevation_model.h"
#include "planet/sources/source_mosaic.h"
#include "planet_commands.h"

#include <cmath>
#include <cstdio>
#include <memory>

namespace globe::cli {
namespace {

Result<glm::dvec2> parseLatLon(const std::string& text) {
  double lat = 0.0;
  double lon = 0.0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf%c", &lat, &lon, &extra) != 2) {
    return Error::inField("--at", "expected LAT,LON in degrees (for example 27.99,86.93), got '" + text + "'");
  }
  if (!std::isfinite(lat) || !std::isfinite(lon))
    return Error::inField("--at", "latitude and longitude must be finite");
  if (lat < -90.0 || lat > 90.0) return Error::inField("--at", "latitude must be within [-90, 90] degrees");
  return glm::dvec2(lat, lon);
}

int runSample(const std::string& file, const std::vector<std::string>& at) {
  std::vector<glm::dvec2> points;
  for (const std::string& a : at) {
    auto p = parseLatLon(a);
    if (!p) return usageError(p.error());
    points.push_back(*p);
  }
  const auto planet = loadPlanetForCommand(file);
  if (!planet) return kExitUsage;
  const ElevationModel model(*planet);
  for (const glm::dvec2& p : points) {
    const glm::dvec3 direction = directionFromLatLon(p.x, p.y);
    if (model.sourceTerm(direction).hole >= 0.5) {
      std::printf("%.9g,%.9g nodata\n", p.x, p.y);
    } else {
      std::printf("%.9g,%.9g %.6f\n", p.x, p.y, model.elevation_m(direction));
    }
  }
  return kExitOk;
}

}  // namespace

void addPlanetSampleCommand(CLI::App& planet, std::function<int()>& run) {
  auto file = std::make_shared<std::string>();
  auto at = std::make_shared<std::vector<std::string>>();
  CLI::App* sample = planet.add_subcommand(
      "sample",
      "Print the elevation that is drawn (metres above radius_m, sources mosaicked) at points, or nodata "
      "inside a kept hole");
  addPlanetFileArgument(*sample, *file);
  sample->add_option("--at", *at, "LAT,LON in degrees; repeat for more points")->required()->allow_extra_args(false);
  sample->callback([file, at, &run] { run = [file, at] { return runSample(*file, *at); }; });
}

}  // namespace globe::cli
