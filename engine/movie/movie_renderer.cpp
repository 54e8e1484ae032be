#include "engine/movie/movie_renderer.h"

#include "engine/movie/lod_log.h"
#ifdef GLOBE_HAS_MP4
#include "engine/movie/mp4_writer.h"
#endif
#include "engine/render/headless_renderer.h"
#include "engine/render/render_output.h"
#include "planet/core/atomic_file.h"
#include "planet/core/input_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

namespace globe {

namespace fs = std::filesystem;

bool isSupportedFrameRate(int fps, MovieFormat format) {
  if (format != MovieFormat::mp4) return fps >= 1 && fps <= kMaxSequenceFrameRate;
  return std::find(std::begin(kMovieFrameRates), std::end(kMovieFrameRates), fps) != std::end(kMovieFrameRates);
}

bool isFormatBuilt(MovieFormat format) {
#ifdef GLOBE_HAS_MP4
  constexpr bool mp4 = true;
#else
  constexpr bool mp4 = false;
#endif
  return format != MovieFormat::mp4 || mp4;
}

uint64_t movieFrameCount(double duration_s, int fps) {
  // The epsilon absorbs rounding in duration * fps (0.3 s at 30 fps is 8.999999999999998).
  return uint64_t(std::floor(duration_s * double(fps) + 1e-9)) + 1;
}

std::string movieFrameName(uint64_t frame, MovieFormat format) {
  return fmt::format("frame_{:06d}.{}", frame, format == MovieFormat::exr ? "exr" : "png");
}

namespace {

// The file beside a sequence saying which movie its frames belong to: resuming with other
// settings would mix two movies in one directory.
constexpr const char* kManifestName = "movie.txt";

Status claimDirectory(const MovieSettings& s) {
  std::error_code ec;
  fs::create_directories(s.out, ec);
  if (ec) return Error::inField("--out", fmt::format("cannot create '{}': {}", s.out, ec.message()));
  const std::string manifest = (fs::path(s.out) / kManifestName).string();
  const std::string content = s.description + "\n";
  std::error_code exists;
  if (fs::exists(fs::symlink_status(manifest, exists))) {
    // The bounded reader: a FIFO or directory named movie.txt is an error, never a wait.
    Result<std::string> old = readInputFile(manifest, "movie manifest");
    if (!old) return Error::inFileField(manifest, "--out", old.error().message);  // bad input, like the next
    if (*old != content)
      return Error::inFileField(
          manifest, "--out",
          "this directory holds frames of another movie (its settings differ); choose another --out or "
          "empty it");
    return Ok{};
  }
  return writeFileAtomically(manifest, content, "--out");
}

bool frameExists(const fs::path& file) {
  std::error_code ec;
  return fs::is_regular_file(file, ec) && fs::file_size(file, ec) > 0;
}

// Everything a frame needs: the terrain, the renderer and the camera's ground.
struct FrameSource {
  vk::Device& device;
  ElevationModel model;
  std::unique_ptr<Terrain> terrain;
  std::unique_ptr<HeadlessRenderer> renderer;
  GroundRadiusFn ground;

  ImageRgba render(const CameraPath& path, double t_s, double aspect) {
    Camera camera = path.cameraAt(t_s, model.radius_m(), aspect, ground, model.shape());
    renderer->renderFrame(*terrain, camera, true);
    return toImage(renderer->readback(), camera);
  }
};

Result<std::unique_ptr<FrameSource>> makeFrameSource(vk::Device& device, const PlanetDescription& planet,
                                                     const CameraPath& path, MovieSettings& s) {
  auto source = std::unique_ptr<FrameSource>(new FrameSource{device, ElevationModel(planet), nullptr, nullptr, {}});
  ElevationModel& model = source->model;
  // One sun for the whole movie, lighting the region of the path's first keyframe (as globe bench):
  // the path's own sun there, else the default.
  const glm::dvec3 start = path.positionAt(
      path.startTime_s(), [&](const glm::dvec3& d) { return model.radius_m() + model.visibleElevation_m(d); },
      model.radius_m());
  const std::optional<SunAngles>& pathSun = path.keyframes().front().sun;
  s.terrain.style.sunDirection = pathSun ? sunDirectionAt(start, *pathSun) : defaultSunDirection(start);
  auto terrain = Terrain::create(device, model, s.terrain);
  if (!terrain) return terrain.error();
  source->terrain = std::move(*terrain);
  source->renderer = std::make_unique<HeadlessRenderer>(device, VkExtent2D{s.width, s.height});
  Terrain* t = source->terrain.get();
  // Heights are above the drawn mesh, like globe render --at and globe bench.
  source->ground = [t](const glm::dvec3& d) { return t->cameraGroundRadius(d); };
  return source;
}

// Brings the terrain's LOD state to what an uninterrupted run had after frame `k - 1` (nothing
// for k = 0: `initial`): from the log, else by rendering the frames since the latest logged one
// again without writing them (a log deleted or cut short). Returns the frames replayed.
Result<uint64_t> restoreStateBefore(uint64_t k, FrameSource& source, const CameraPath& path, const MovieSettings& s,
                                    LodLog& log, const LodRanges::Observations& initial) {
  if (k == 0) {
    source.terrain->restoreLodObservations(initial);
    return uint64_t{0};
  }
  if (const LodRanges::Observations* logged = log.after(k - 1)) {
    source.terrain->restoreLodObservations(*logged);
    return uint64_t{0};
  }
  const std::optional<uint64_t> latest = log.latestBefore(k - 1);
  source.terrain->restoreLodObservations(latest ? *log.after(*latest) : initial);
  const double aspect = double(s.width) / double(s.height);
  uint64_t replayed = 0;
  for (uint64_t j = latest ? *latest + 1 : 0; j < k; ++j, ++replayed) {
    source.render(path, path.startTime_s() + double(j) / s.fps, aspect);
    if (Status st = log.record(j, source.terrain->lodObservations()); !st) return st.error();
  }
  return replayed;
}

Result<MovieSummary> renderSequence(FrameSource& source, const CameraPath& path, const MovieSettings& s,
                                    const MovieProgressFn& progress) {
  Result<LodLog> log = LodLog::open(s.out);
  if (!log) return log.error();
  const LodRanges::Observations initial = source.terrain->lodObservations();
  MovieSummary summary;
  summary.frames = movieFrameCount(path.duration_s(), s.fps);
  const double aspect = double(s.width) / double(s.height);
  std::optional<uint64_t> lastRendered;  // the terrain's state is the one after this frame
  for (uint64_t k = 0; k < summary.frames; ++k) {
    const fs::path file = fs::path(s.out) / movieFrameName(k, s.format);
    if (frameExists(file)) {
      ++summary.kept;
    } else {
      if (!(k > 0 && lastRendered == k - 1)) {
        Result<uint64_t> replayed = restoreStateBefore(k, source, path, s, *log, initial);
        if (!replayed) return replayed.error();
        summary.replayed += *replayed;
      }
      ImageRgba image = source.render(path, path.startTime_s() + double(k) / s.fps, aspect);
      // Logged before the frame is written: a frame on disk always has its state logged.
      if (Status st = log->record(k, source.terrain->lodObservations()); !st) return st.error();
      Status written = s.format == MovieFormat::exr ? writeExr(file.string(), image) : writePng(file.string(), image);
      if (!written) return written.error();
      ++summary.rendered;
      lastRendered = k;
    }
    if (progress) progress(k + 1, summary.frames, *source.terrain);
  }
  return summary;
}

Result<MovieSummary> renderMp4(FrameSource& source, const CameraPath& path, const MovieSettings& s,
                               const MovieProgressFn& progress) {
#ifndef GLOBE_HAS_MP4
  (void)source, (void)path, (void)progress;
  return Error::inField("--out",
                        "'" + s.out + "': this globe was built without FFmpeg, it writes PNG/EXR sequences only");
#else
  removeStaleTemporaries(s.out);  // a killed earlier run's .NAME.mp4.tmpPID
  AtomicFile file(s.out);
  if (auto made = makeParentDirectories(s.out); !made) return made.error();
  auto writer = Mp4Writer::open(file.tempPath(), s.width, s.height, s.fps);
  if (!writer) return writer.error();
  MovieSummary summary;
  summary.frames = movieFrameCount(path.duration_s(), s.fps);
  summary.encoder = (*writer)->encoderDescription();
  const double aspect = double(s.width) / double(s.height);
  for (uint64_t k = 0; k < summary.frames; ++k) {
    ImageRgba image = source.render(path, path.startTime_s() + double(k) / s.fps, aspect);
    if (Status st = (*writer)->addFrame(image); !st) return st.error();
    ++summary.rendered;
    if (progress) progress(k + 1, summary.frames, *source.terrain);
  }
  if (Status st = (*writer)->finish(); !st) return st.error();
  if (Status st = file.commit(); !st) return st.error();
  return summary;
#endif
}
}  // namespace

Result<MovieSummary> renderMovie(vk::Device& device, const PlanetDescription& planet, const CameraPath& path,
                                 MovieSettings settings, const MovieProgressFn& progress) {
  const auto start = std::chrono::steady_clock::now();
  if (settings.format != MovieFormat::mp4)
    if (Status s = claimDirectory(settings); !s) return s.error();
  auto source = makeFrameSource(device, planet, path, settings);
  if (!source) return source.error();
  auto summary = settings.format == MovieFormat::mp4 ? renderMp4(**source, path, settings, progress)
                                                     : renderSequence(**source, path, settings, progress);
  if (summary) summary->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace globe
