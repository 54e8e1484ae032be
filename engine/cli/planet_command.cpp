// globe planet: check, stats (and sample, planet_sample_command.cpp; export, planet_export_command.cpp).
#include "commands.h"
#include "options.h"
#include "planet/camera/camera.h"
#include "planet/model/elevation_model.h"
#include "planet/model/planet_file.h"
#include "planet/model/source_report.h"
#include "planet/model/sphere_sampling.h"
#include "planet/model/surface_sample.h"
#include "planet_commands.h"
#include "progress_bar.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

namespace globe::cli {

std::optional<PlanetDescription> loadPlanetForCommand(const std::string& path) {
  PlanetFileCheck check = checkPlanetFile(path);
  if (check.ok()) return std::move(check.planet);
  std::string message = check.errors.front().format();
  if (check.errors.size() > 1) {
    message += fmt::format(" (and {} more: globe planet check {})", check.errors.size() - 1, path);
  }
  printError(message);
  return std::nullopt;
}

unsigned defaultThreads() { return std::max(1U, std::thread::hardware_concurrency()); }

void addThreadsOption(CLI::App& cmd, unsigned& threads) {
  threads = defaultThreads();
  cmd.add_option("--threads", threads, "Worker threads (default: every hardware thread)")
      ->check(CLI::Range(1U, 256U))
      ->capture_default_str();
}

namespace {

// ---- check ----

int runCheck(const std::vector<std::string>& files) {
  int code = kExitOk;
  for (const std::string& file : files) {
    const PlanetFileCheck check = checkPlanetFile(file);
    if (check.ok()) {
      std::printf("%s: ok\n", file.c_str());
      for (const std::string& line : describeSources(check.planet)) std::printf("  %s\n", line.c_str());
      continue;
    }
    for (const std::string& line : formatErrorList(check.errors)) std::fprintf(stderr, "%s\n", line.c_str());
    std::fprintf(stderr, "%s: %zu problem%s\n", file.c_str(), check.errors.size(), check.errors.size() == 1 ? "" : "s");
    code = kExitUsage;
  }
  std::fflush(stdout);
  return code;
}

// ---- stats ----

struct StatsOptions {
  std::string file;
  std::uint64_t samples = 1000000;
  int bins = 20;
  unsigned threads = 1;
};

// One line per land cover class, `land_cover NAME PERCENT` (of the planet's area), after
// `land_cover sea PERCENT` on a planet with [water]; nothing without land cover.
std::string landCoverLines(const ElevationModel& model, const PlanetDescription& planet, const StatsOptions& o) {
  if (!planet.land_cover.enabled()) return {};
  const auto start = std::chrono::steady_clock::now();
  LandCoverShares shares;
  {
    ProgressBar bar("land cover");
    shares = computeLandCoverShares(model, o.samples, o.threads, [&bar](double f) { bar.update(f); });
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::string out;
  auto line = std::back_inserter(out);
  fmt::format_to(line, "land cover (% of the planet's area, same samples, slopes over {} m): {:.2f} s\n",
                 kLandCoverSlopeSpacing_m, seconds);
  if (model.drawsWater()) fmt::format_to(line, "land_cover sea {:.1f}\n", 100.0 * shares.sea_fraction);
  for (std::size_t i = 0; i < shares.class_fraction.size(); ++i) {
    fmt::format_to(line, "land_cover {} {:.1f}\n", planet.land_cover.classes[i].name, 100.0 * shares.class_fraction[i]);
  }
  return out;
}

int runStats(const StatsOptions& o) {
  const auto planet = loadPlanetForCommand(o.file);
  if (!planet) return kExitUsage;
  const ElevationModel model(*planet);
  const auto start = std::chrono::steady_clock::now();
  ElevationStats s;
  {
    ProgressBar bar("sampling");
    s = computeElevationStats(model, o.samples, o.bins, o.threads, [&bar](double f) { bar.update(f); });
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const ElevationRange bounds = model.bounds();
  std::string out;
  auto line = std::back_inserter(out);
  fmt::format_to(line, "planet {}: radius {} m, sea level {} m, default quality {}\n",
                 escapeControlCharacters(planet->name), planet->radius_m, planet->sea_level_m,
                 qualityPresetName(planet->default_quality));
  fmt::format_to(line, "samples: {} uniform directions (Fibonacci sphere), {} threads, {:.2f} s ({:.2f} M/s)\n",
                 s.samples, o.threads, seconds, static_cast<double>(s.samples) / seconds * 1e-6);
  fmt::format_to(line, "elevation: min {:.1f} m, max {:.1f} m, mean {:.1f} m\n", s.min_m, s.max_m, s.mean_m);
  fmt::format_to(line, "percentiles: 1% {:.1f} m, median {:.1f} m, 99% {:.1f} m\n", s.p01_m, s.median_m, s.p99_m);
  fmt::format_to(line, "below sea level: {:.2f} % of the surface\n", 100.0 * s.below_sea_fraction);
  fmt::format_to(line, "conservative bounds: {:.1f} .. {:.1f} m\n", bounds.min_m, bounds.max_m);
  fmt::format_to(line, "hypsometry (area of each elevation band; area at or above the band's floor):\n");
  double above = 1.0;
  double largest = 0.0;
  for (double f : s.histogram) largest = std::max(largest, f);
  const double band = (s.max_m - s.min_m) / static_cast<double>(s.histogram.size());
  for (std::size_t i = 0; i < s.histogram.size(); ++i) {
    const double lo = s.min_m + band * static_cast<double>(i);
    const double f = s.histogram[i];
    const auto bar = static_cast<std::size_t>(std::lround(largest > 0.0 ? 40.0 * f / largest : 0.0));
    fmt::format_to(line, "  {:>12.1f} .. {:>12.1f} m {:>7.2f} % {:>7.2f} %  {}\n", lo, lo + band, 100.0 * f,
                   100.0 * std::max(above, 0.0), std::string(bar, '#'));
    above -= f;
  }
  out += landCoverLines(model, *planet, o);
  std::fputs(out.c_str(), stdout);
  return kExitOk;
}

}  // namespace

void addPlanetFileArgument(CLI::App& cmd, std::string& file) {
  file = defaultPlanetPath();
  cmd.add_option("FILE", file, "Planet file (default: the earthlike preset)");
}

void addPlanetCommand(CLI::App& app, Runner& run) {
  CLI::App* planet = app.add_subcommand("planet", "Author planet files: check, stats, sample, export");
  planet->require_subcommand(1);

  auto files = std::make_shared<std::vector<std::string>>();
  CLI::App* check = planet->add_subcommand(
      "check", "Report every problem of planet files as FILE:LINE:COLUMN: KEY: MESSAGE; exit 0 only if all are valid");
  check->add_option("FILE", *files, "Planet files (default: the earthlike preset)");
  check->callback([files, &run] {
    if (files->empty()) files->push_back(defaultPlanetPath());
    run = [files] { return runCheck(*files); };
  });

  auto stats = std::make_shared<StatsOptions>();
  CLI::App* stats_cmd = planet->add_subcommand(
      "stats",
      "Elevation statistics over uniform directions: min/max/mean, percentiles, hypsometry, area below sea, "
      "land cover shares");
  addPlanetFileArgument(*stats_cmd, stats->file);
  stats_cmd->add_option("--samples", stats->samples, "Directions sampled (Fibonacci sphere)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{100000000}))
      ->capture_default_str();
  stats_cmd->add_option("--bins", stats->bins, "Hypsometry bands")->check(CLI::Range(1, 200))->capture_default_str();
  addThreadsOption(*stats_cmd, stats->threads);
  stats_cmd->callback([stats, &run] { run = [stats] { return runStats(*stats); }; });

  addPlanetSampleCommand(*planet, run);
  addPlanetExportCommand(*planet, run);
}

}  // namespace globe::cli
