// globe planet export: an equirectangular float32 elevation map (OpenEXR, channel Y, metres) and an
// optional shaded, ramp-coloured PNG preview. Written atomically: a failed or interrupted export
// leaves no target file (see engine/io/elevation_exr.h and signal_cleanup.h).
#include "commands.h"
#include "engine/io/elevation_exr.h"
#include "engine/io/image_io.h"
#include "options.h"
#include "planet/core/atomic_file.h"
#include "planet/elevation/colour_ramp.h"
#include "planet/elevation/elevation.h"
#include "planet/elevation/equirect_preview.h"
#include "planet_commands.h"
#include "progress_bar.h"
#include "signal_cleanup.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

namespace globe::cli {

namespace {

struct ExportOptions {
  std::string file;
  std::uint32_t width = 0;
  std::string out;
  std::string png;
  std::uint32_t png_width = 0;  // 0: min(width, 4096)
  unsigned threads = 1;
};

bool hasExtension(const std::string& path, const char* ext) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e == ext;
}

Status checkWidth(std::uint32_t width, const std::string& field) {
  if (width < 2 || width > 65536 || width % 2 != 0) {
    return Error::inField(field, "must be even and within [2, 65536] pixels, got " + std::to_string(width));
  }
  return Ok{};
}

// Everything a user can get wrong is refused before any work, with nothing written.
Status checkOptions(ExportOptions& o) {
  if (auto s = checkWidth(o.width, "--width"); !s) return s;
  if (!hasExtension(o.out, ".exr")) return Error::inField("--out", "'" + o.out + "' must end in .exr");
  if (auto s = checkWritable(o.out, "--out"); !s) return s;
  if (!o.png.empty()) {
    if (!hasExtension(o.png, ".png")) return Error::inField("--png", "'" + o.png + "' must end in .png");
    if (auto s = checkWritable(o.png, "--png"); !s) return s;
    if (o.png_width == 0) o.png_width = std::min<std::uint32_t>(o.width, 4096);
    if (auto s = checkWidth(o.png_width, "--png-width"); !s) return s;
    if (std::filesystem::absolute(o.png) == std::filesystem::absolute(o.out)) {
      return Error::inField("--png", "must differ from --out");
    }
  }
  return Ok{};
}

Status writePreview(const ElevationModel& model, const PlanetDescription& planet, const ExportOptions& o,
                    std::vector<float> elevation) {
  const std::uint32_t w = o.png_width;
  const std::uint32_t h = w / 2;
  if (elevation.empty()) {  // a smaller preview than the map: sample it at its own size
    elevation.resize(static_cast<std::size_t>(w) * h);
    ProgressBar bar("preview");
    sampleEquirectRows(model, w, h, 0, elevation, o.threads, [&bar](double f) { bar.update(f); });
  }
  const std::vector<glm::vec3> rgb = shadeEquirect(elevation, w, h, planet);
  ImageRgba image;
  image.width = w;
  image.height = h;
  image.rgba.resize(rgb.size() * 4);
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    image.rgba[i * 4 + 0] = rgb[i].x;
    image.rgba[i * 4 + 1] = rgb[i].y;
    image.rgba[i * 4 + 2] = rgb[i].z;
    image.rgba[i * 4 + 3] = 1.0f;
  }
  return writePng(o.png, image);
}

int runExport(ExportOptions o) {
  if (auto s = checkOptions(o); !s) return usageError(s.error());
  const auto planet = loadPlanetForCommand(o.file);
  if (!planet) return kExitUsage;
  const ElevationModel model(*planet);

  const auto start = std::chrono::steady_clock::now();
  std::vector<float> keep;
  {
    AtomicFile file(o.out);
    const RemoveOnSignal cleanup(file.tempPath());
    ElevationExportOptions eo;
    eo.width = o.width;
    eo.threads = o.threads;
    eo.planet_name = planet->name;
    eo.keep = !o.png.empty() && o.png_width == o.width ? &keep : nullptr;
    Status s = [&] {
      ProgressBar bar("exporting");
      return writeElevationExr(model, eo, file, [&bar](double f) { bar.update(f); });
    }();
    if (s) s = file.commit();
    if (!s) {
      printError(s.error().format());
      return kExitFailure;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double samples = static_cast<double>(o.width) * (o.width / 2);
  std::printf("wrote %s (%ux%u, float elevation in metres, channel Y; %.2f s, %.2f M samples/s, %u threads)\n",
              o.out.c_str(), o.width, o.width / 2, seconds, samples / seconds * 1e-6, o.threads);
  if (!o.png.empty()) {
    if (Status s = writePreview(model, *planet, o, std::move(keep)); !s) {
      printError(s.error().format());
      return kExitFailure;
    }
    std::printf("wrote %s (%ux%u preview)\n", o.png.c_str(), o.png_width, o.png_width / 2);
  }
  std::fflush(stdout);
  return kExitOk;
}

}  // namespace

void addPlanetExportCommand(CLI::App& planet, std::function<int()>& run) {
  auto o = std::make_shared<ExportOptions>();
  CLI::App* cmd = planet.add_subcommand(
      "export", "Write an equirectangular float32 elevation map (OpenEXR, channel Y, metres), W x W/2 pixels");
  o->file = defaultPlanetPath();
  cmd->add_option("FILE", o->file, "Planet file (default: the earthlike preset)");
  cmd->add_option("--width", o->width, "Map width W in pixels, even, [2, 65536]; the height is W/2")->required();
  cmd->add_option("--out", o->out, "Output .exr file (written atomically)")->required();
  cmd->add_option("--png", o->png, "Also write a shaded, ramp-coloured preview .png");
  cmd->add_option("--png-width", o->png_width, "Preview width in pixels (default: min(W, 4096))")
      ->check(CLI::Range(2U, 65536U));
  addThreadsOption(*cmd, o->threads);
  cmd->callback([o, &run] { run = [o] { return runExport(*o); }; });
}

}  // namespace globe::cli
