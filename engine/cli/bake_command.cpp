// globe bake: export a planet as standard terrain tiles (quantized mesh for Cesium clients, or
// Cloud-Optimized GeoTIFF height rasters), one shard of a bake at a time (docs/bake.md). Every
// option is checked before anything is written; every tile is written atomically.
#include "commands.h"
#include "engine/bake/baker.h"
#include "options.h"
#include "planet/core/atomic_file.h"
#include "planet_commands.h"
#include "progress_bar.h"
#include "signal_cleanup.h"

#include <chrono>
#include <cstdio>

namespace globe::cli {

namespace {

struct BakeOptions {
  std::string planet;
  std::string format;
  std::string levels;
  std::string region = "-180,-90,180,90";
  std::string shard = "0/1";
  std::string out;
  unsigned threads = 1;
  DeviceFlags device;
};

Result<BakeSettings> checkOptions(const BakeOptions& o) {
  BakeSettings s;
  auto format = parseBakeFormat(o.format, "--format");
  if (!format) return format.error();
  auto levels = parseLevelRange(o.levels, "--levels");
  if (!levels) return levels.error();
  auto region = parseRegion(o.region, "--region");
  if (!region) return region.error();
  auto shard = parseShard(o.shard, "--shard");
  if (!shard) return shard.error();
  if (auto ok = checkOutputDirectory(o.out, "--out"); !ok) return ok.error();
  s.format = *format;
  s.levels = *levels;
  s.region = *region;
  s.shard = *shard;
  s.out_dir = o.out;
  s.threads = o.threads;
  return s;
}

// AtomicFile, with the temporary removed if Ctrl-C (or a scheduler's SIGTERM) lands mid-write.
Status writeTile(const std::string& path, std::string_view bytes) {
  AtomicFile file(path);
  const RemoveOnSignal cleanup(file.tempPath());
  if (auto s = file.write(bytes); !s) return s;
  return file.commit();
}

int runBakeCommand(const BakeOptions& o) {
  auto settings = checkOptions(o);
  if (!settings) return usageError(settings.error());
  const auto planet = loadPlanetForCommand(o.planet);
  if (!planet) return kExitUsage;
  const ElevationModel model(*planet);
  vk::Device device(deviceOptions(o.device));
  printDeviceChoice(device);
  GpuHeightSampler heights(device, model, o.threads);
  const auto start = std::chrono::steady_clock::now();
  Result<BakeSummary> summary = [&] {
    ProgressBar bar("baking");
    return runBake(*planet, heights, *settings, writeTile, [&bar](double f) { bar.update(f); });
  }();
  if (!summary) {
    printError(summary.error().format());
    return kExitFailure;
  }
  if (int code = validationExitCode(device); code != kExitOk) return code;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "baked %s shard %u/%u: %llu of %llu tiles written, %llu already there (plan: %llu tiles); "
      "%.2f s, %.1f tiles/s, %u threads, %s\n",
      bakeFormatName(settings->format), settings->shard.index, settings->shard.count,
      static_cast<unsigned long long>(summary->written), static_cast<unsigned long long>(summary->shard_tiles),
      static_cast<unsigned long long>(summary->skipped), static_cast<unsigned long long>(summary->plan_tiles), seconds,
      seconds > 0.0 ? double(summary->written) / seconds : 0.0, o.threads, device.name().c_str());
  if (summary->written > 0) {
    std::printf("  heights %.2f s, meshes/encoding %.2f s, writes %.2f s; %.1f KiB per tile", summary->heights_s,
                summary->encode_s, summary->write_s, double(summary->bytes) / double(summary->written) / 1024.0);
    if (settings->format == BakeFormat::QuantizedMesh) {
      std::printf(", %llu vertices per tile", static_cast<unsigned long long>(summary->vertices / summary->written));
    }
    std::printf("\n");
  }
  std::fflush(stdout);
  return kExitOk;
}

}  // namespace

void addBakeCommand(CLI::App& app, Runner& run) {
  auto o = std::make_shared<BakeOptions>();
  CLI::App* cmd = app.add_subcommand("bake", "Export the planet as terrain tiles: quantized mesh (Cesium) or COG");
  o->planet = defaultPlanetPath();
  cmd->add_option("--planet", o->planet, "Planet file (default: the earthlike preset)");
  cmd->add_option("--format", o->format, "quantized-mesh (DIR/{level}/{x}/{y}.terrain + layer.json) or cog")
      ->required();
  cmd->add_option("--levels", o->levels, "Tile levels A..B (0 = the two root tiles)")->required();
  cmd->add_option("--region", o->region, "W,S,E,N in degrees: bake the tiles overlapping it (level 0 is whole)")
      ->capture_default_str();
  cmd->add_option("--shard", o->shard, "K/N: bake shard K (from 0) of N; the shards together make the bake")
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Output directory (created; finished tiles are kept and skipped)")->required();
  addThreadsOption(*cmd, o->threads);
  addDeviceFlags(*cmd, o->device);
  cmd->callback([o, &run] { run = [o] { return runBakeCommand(*o); }; });
}

}  // namespace globe::cli
