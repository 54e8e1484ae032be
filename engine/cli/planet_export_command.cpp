// globe planet export: an equirectangular float32 elevation map (OpenEXR, channel Y, metres), an
// optional shaded PNG preview (coloured by the ramp, or by the land cover when the planet has one)
// and an optional land cover map (the albedo of each pixel's masks, the sea by depth). Written
// atomically: a failed or interrupted export leaves no target file (see engine/io/elevation_exr.h
// and signal_cleanup.h).
#include "commands.h"
#include "engine/io/elevation_exr.h"
#include "engine/io/image_io.h"
#include "options.h"
#include "planet/core/atomic_file.h"
#include "planet/model/elevation_model.h"
#include "planet/model/equirect_preview.h"
#include "planet/model/surface_sample.h"
#include "planet/surface/colour_ramp.h"
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
  std::string land_cover;       // the land cover map (.png), at png_width
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
  for (const auto& [path, field] : {std::pair{&o.png, "--png"}, std::pair{&o.land_cover, "--land-cover"}}) {
    if (path->empty()) continue;
    if (!hasExtension(*path, ".png")) return Error::inField(field, "'" + *path + "' must end in .png");
    if (auto s = checkWritable(*path, field); !s) return s;
    if (std::filesystem::absolute(*path) == std::filesystem::absolute(o.out)) {
      return Error::inField(field, "must differ from --out");
    }
  }
  if (!o.png.empty() && !o.land_cover.empty() &&
      std::filesystem::absolute(o.png) == std::filesystem::absolute(o.land_cover)) {
    return Error::inField("--land-cover", "must differ from --png");
  }
  if (!o.png.empty() || !o.land_cover.empty()) {
    if (o.png_width == 0) o.png_width = std::min<std::uint32_t>(o.width, 4096);
    if (auto s = checkWidth(o.png_width, "--png-width"); !s) return s;
  }
  return Ok{};
}

Status writeRgbPng(const std::string& path, std::uint32_t width, std::span<const glm::vec3> rgb) {
  ImageRgba image;
  image.width = width;
  image.height = static_cast<std::uint32_t>(rgb.size() / width);
  image.rgba.resize(rgb.size() * 4);
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    image.rgba[i * 4 + 0] = rgb[i].x;
    image.rgba[i * 4 + 1] = rgb[i].y;
    image.rgba[i * 4 + 2] = rgb[i].z;
    image.rgba[i * 4 + 3] = 1.0f;
  }
  return writePng(path, image);
}

// The PNGs, at --png-width: the land cover map (computed once; also the preview's ground colour on a
// planet with land cover) and the shaded preview. Each file is written atomically.
Status writePreviews(const ElevationModel& model, const PlanetDescription& planet, const ExportOptions& o,
                     std::vector<float> elevation) {
  if (o.png.empty() && o.land_cover.empty()) return Ok{};
  const std::uint32_t w = o.png_width;
  const std::uint32_t h = w / 2;
  std::vector<glm::vec3> albedo;
  if (planet.land_cover.enabled()) {
    albedo.resize(static_cast<std::size_t>(w) * h);
    ProgressBar bar("land cover");
    landCoverEquirectRows(model, w, h, 0, albedo, o.threads, [&bar](double f) { bar.update(f); });
  }
  if (!o.land_cover.empty()) {
    if (Status s = writeRgbPng(o.land_cover, w, albedo); !s) return s;
    std::printf("wrote %s (%ux%u land cover map)\n", o.land_cover.c_str(), w, h);
  }
  if (o.png.empty()) return Ok{};
  if (elevation.empty()) {  // a smaller preview than the map: sample it at its own size
    elevation.resize(static_cast<std::size_t>(w) * h);
    ProgressBar bar("preview");
    sampleEquirectRows(model, w, h, 0, elevation, o.threads, [&bar](double f) { bar.update(f); });
  }
  if (Status s = writeRgbPng(o.png, w, shadeEquirect(elevation, w, h, planet, albedo)); !s) return s;
  std::printf("wrote %s (%ux%u preview)\n", o.png.c_str(), w, h);
  return Ok{};
}

int runExport(ExportOptions o) {
  if (auto s = checkOptions(o); !s) return usageError(s.error());
  const auto planet = loadPlanetForCommand(o.file);
  if (!planet) return kExitUsage;
  if (!o.land_cover.empty() && !planet->land_cover.enabled()) {
    return usageError(Error::inField("--land-cover", "the planet has no [[land_cover]] classes"));
  }
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
  if (Status s = writePreviews(model, *planet, o, std::move(keep)); !s) {
    printError(s.error().format());
    return kExitFailure;
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
  cmd->add_option("--png", o->png, "Also write a shaded preview .png (ramp or land cover colours)");
  cmd->add_option("--land-cover", o->land_cover,
                  "Also write the land cover map .png (albedo of the masks, the sea by depth), --png-width wide");
  cmd->add_option("--png-width", o->png_width, "Width of the preview and land cover map (default: min(W, 4096))")
      ->check(CLI::Range(2U, 65536U));
  addThreadsOption(*cmd, o->threads);
  cmd->callback([o, &run] { run = [o] { return runExport(*o); }; });
}

}  // namespace globe::cli
