// globe movie: a camera path rendered frame by frame at a fixed rate, every frame converged, as a
// PNG/EXR sequence or an MP4 (engine/movie).
#include "commands.h"
#include "engine/movie/lod_log.h"
#include "engine/movie/movie_renderer.h"
#include "engine/render/quality.h"
#include "options.h"
#include "planet/core/atomic_file.h"
#include "planet/model/planet_file.h"
#include "planet/paths/camera_path_file.h"
#include "progress_bar.h"
#include "signal_cleanup.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <optional>

namespace globe::cli {

namespace {

struct MovieOptions {
  DeviceFlags device;
  std::string planet;
  std::string path;
  std::string out = "out/movie";
  std::string size = "640x360";
  std::string format = "png";
  int fps = 30;
  QualityOptions quality;  // --quality, --tolerance
  BudgetOptions budget;
};

bool endsWithMp4(const std::string& file) {
  std::string e = std::filesystem::path(file).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e == ".mp4";
}

// Everything checked before anything is written: bad input writes nothing.
Result<MovieSettings> movieSettings(const MovieOptions& o, const PlanetDescription& planet) {
  MovieSettings s;
  auto size = parseSize(o.size, "--size");
  if (!size) return size.error();
  s.width = size->width;
  s.height = size->height;
  if (endsWithMp4(o.out)) {
    s.format = MovieFormat::mp4;
    if (!isFormatBuilt(MovieFormat::mp4))
      return Error::inField("--out", "'" + o.out +
                                         "': this globe was built without FFmpeg (GLOBE_WITH_FFMPEG=OFF), it writes "
                                         "PNG/EXR sequences only: give a directory");
    if (s.width % 2 || s.height % 2)
      return Error::inField("--size", fmt::format("H.264 needs an even width and height, got {}", o.size));
    if (auto st = checkWritable(o.out, "--out"); !st) return st.error();
  } else {
    if (std::filesystem::path(o.out).has_extension())
      return Error::inField("--out", "must be a directory (for a frame sequence) or a .mp4 file, got '" + o.out + "'");
    if (o.format != "png" && o.format != "exr")
      return Error::inField("--format", "must be png or exr, got '" + o.format + "'");
    s.format = o.format == "exr" ? MovieFormat::exr : MovieFormat::png;
    if (auto st = checkOutputDirectory(o.out, "--out"); !st) return st.error();
  }
  if (!isSupportedFrameRate(o.fps, s.format))
    return Error::inField("--fps", s.format == MovieFormat::mp4
                                       ? fmt::format("an MP4 takes 24, 25, 30, 50 or 60, got {} (an image sequence "
                                                     "takes any rate from 1 to {})",
                                                     o.fps, kMaxSequenceFrameRate)
                                       : fmt::format("must be within [1, {}], got {}", kMaxSequenceFrameRate, o.fps));
  s.fps = o.fps;
  s.out = o.out;
  auto terrain = renderSettingsFromOptions(o.quality, o.budget, planet, *size, s.format == MovieFormat::mp4);
  if (!terrain) return terrain.error();
  s.terrain = *terrain;
  s.description = fmt::format("path={} planet={} size={}x{} fps={} format={} quality={}{}", o.path, o.planet, s.width,
                              s.height, s.fps, o.format, o.quality.quality.empty() ? "default" : o.quality.quality,
                              o.quality.tolerance_px > 0 ? fmt::format(" tolerance={}", o.quality.tolerance_px) : "");
  return s;
}

int runMovie(const MovieOptions& o) {
  auto planet = loadPlanetFile(o.planet);
  if (!planet) return usageError(planet.error());
  auto path = loadCameraPath(o.path);
  if (!path) return usageError(path.error());
  auto settings = movieSettings(o, *planet);
  if (!settings) return usageError(settings.error());

  // Ctrl-C during an MP4 leaves no temporary behind (AtomicFile names it the same in this process).
  std::optional<RemoveOnSignal> cleanup;
  if (settings->format == MovieFormat::mp4) cleanup.emplace(AtomicFile(o.out).tempPath());
  vk::Device device(deviceOptions(o.device));
  printDeviceChoice(device);
  ProgressBar progress("movie " + std::filesystem::path(o.path).filename().string());
  TerrainWarnings warnings;
  auto summary = renderMovie(device, *planet, *path, *settings, [&](uint64_t done, uint64_t total, const Terrain& t) {
    printNewWarnings(warnings, t);
    progress.update(double(done) / double(total));
  });
  progress.finish();
  if (!summary) {
    // An --out directory holding another movie is bad input (nothing was written); the rest failed.
    // A VRAM budget too small for the 30 roots is the option's fault, named by it.
    const Error error = budgetOptionError(summary.error());
    if (error.field.starts_with("--")) return usageError(error);
    printError(error.format());
    return kExitFailure;
  }
  if (int code = validationExitCode(device); code != kExitOk) return code;
  const MovieSummary& m = *summary;
  const double rate = m.seconds > 0 ? double(m.rendered) / m.seconds : 0.0;
  std::printf("wrote %s: %llu frames at %d fps (%.3f s), %ux%u, %llu rendered, %llu kept, %.2f frames/s (%s)\n",
              o.out.c_str(), (unsigned long long)m.frames, settings->fps, double(m.frames) / settings->fps,
              settings->width, settings->height, (unsigned long long)m.rendered, (unsigned long long)m.kept, rate,
              device.name().c_str());
  if (!m.encoder.empty()) std::printf("encoder: %s\n", m.encoder.c_str());
  if (m.replayed)
    std::printf("replayed %llu earlier frames unwritten: %s lacked their LOD state (docs/camera-paths.md)\n",
                (unsigned long long)m.replayed, kLodLogName);
  return kExitOk;
}

}  // namespace

void addMovieCommand(CLI::App& app, Runner& run) {
  auto o = std::make_shared<MovieOptions>();
  o->planet = defaultPlanetPath();
  const bool mp4 = isFormatBuilt(MovieFormat::mp4);
  CLI::App* cmd = app.add_subcommand(
      "movie", std::string("Render a camera path frame by frame (every frame converged) to a PNG/EXR sequence") +
                   (mp4 ? " or an MP4" : ""));
  cmd->add_option("--path", o->path, "Camera path (.path, .kml tour or .czml)")->required();
  cmd->add_option("--planet", o->planet, "Planet file (TOML)")->capture_default_str();
  cmd->add_option("--fps", o->fps,
                  "Frames per second: 24, 25, 30, 50 or 60 for an MP4, 1 to 1000 for an image sequence")
      ->capture_default_str();
  cmd->add_option("--size", o->size, "Frame size WxH in pixels (even for MP4)")->capture_default_str();
  addQualityOptions(*cmd, o->quality, /*withGrid=*/false);
  addBudgetOptions(*cmd, o->budget);
  cmd->add_option("--out", o->out,
                  std::string("A directory (frame_000000.png ..., resumable)") +
                      (mp4 ? " or a .mp4 file (H.264 through FFmpeg's libraries)" : "; this build writes no MP4"))
      ->capture_default_str();
  cmd->add_option("--format", o->format, "Frame files of a sequence: png (8-bit sRGB) or exr (half RGB + Z)")
      ->capture_default_str();
  addDeviceFlags(*cmd, o->device);
  cmd->callback([o, &run] { run = [o] { return runMovie(*o); }; });
}

}  // namespace globe::cli
