#include "options.h"

#include "commands.h"
#include "planet/core/atomic_file.h"
#include "planet/core/data_directory.h"
#include "shaders/include/payload_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string_view>

namespace globe::cli {

namespace {

// A whole number of digits only; nullopt on anything else, overflow included (sscanf's %u wraps
// 4294967312 to 16).
std::optional<std::uint64_t> parsePixels(std::string_view digits) {
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
  return value;
}

// Whole MiB of `bytesPerPixel` a pixel (sides <= 16384 and bytesPerPixel < 256: no overflow).
std::uint64_t imageMemoryMiB(std::uint64_t width, std::uint64_t height, std::uint64_t bytesPerPixel) {
  return (width * height * bytesPerPixel) >> 20;
}
}  // namespace

Result<ImageSize> parseSize(const std::string& text, const std::string& field) {
  const size_t x = text.find_first_of("xX");
  const auto w = x == std::string::npos ? std::nullopt : parsePixels(std::string_view(text).substr(0, x));
  const auto h = x == std::string::npos ? std::nullopt : parsePixels(std::string_view(text).substr(x + 1));
  if (!w || !h) return Error::inField(field, "expected WxH (for example 1280x720), got '" + text + "'");
  if (*w < kMinImageSidePx || *h < kMinImageSidePx || *w > kMaxImageSidePx || *h > kMaxImageSidePx)
    return Error::inField(field, fmt::format("width and height must be within [{}, {}] pixels, got '{}'",
                                             kMinImageSidePx, kMaxImageSidePx, text));
  const std::uint64_t needMiB = imageMemoryMiB(*w, *h, kRenderBytesPerPixel);
  if (needMiB > kMaxImageMemoryMiB)
    return Error::inField(
        field, fmt::format("{} would need about {} MiB of image memory, more than the limit of {} MiB", text, needMiB,
                           kMaxImageMemoryMiB));
  return ImageSize{static_cast<uint32_t>(*w), static_cast<uint32_t>(*h)};
}

Status checkImageMemory(ImageSize size, Antialiasing aa, bool mp4) {
  std::uint64_t perPixel = aa == Antialiasing::kMsaa4  ? kMsaa4BytesPerPixel
                           : aa == Antialiasing::kFxaa ? kFxaaBytesPerPixel
                                                       : kRenderBytesPerPixel;
  if (mp4) perPixel += kMp4BytesPerPixel;
  const std::uint64_t needMiB = imageMemoryMiB(size.width, size.height, perPixel);
  if (needMiB <= kMaxImageMemoryMiB) return Ok{};
  return Error::inField("--size", fmt::format("{}x{} with --aa {}{} would need about {} MiB of image memory, more than "
                                              "the limit of {} MiB",
                                              size.width, size.height, antialiasingName(aa), mp4 ? " into an MP4" : "",
                                              needMiB, kMaxImageMemoryMiB));
}

CLI::Validator nonEmptyValue() {
  return CLI::Validator([](const std::string& value) { return value.empty() ? std::string("must not be empty") : ""; },
                        "", "NONEMPTY");
}

Status checkOutputDirectory(const std::string& dir, const std::string& field) {
  std::filesystem::path path(dir);
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_directory(path, ec))
    return Error::inField(field, "'" + dir + "' exists and is not a directory");
  return checkCreatableDirectory(dir, field);
}

Status makeOutputDirectory(const std::string& dir, const std::string& field) {
  std::error_code ec;
  if (std::filesystem::is_directory(dir, ec)) return Ok{};
  std::filesystem::create_directories(dir, ec);
  if (ec) return Error::inField(field, "cannot create '" + dir + "': " + ec.message());
  std::printf("made directory '%s' (%s)\n", dir.c_str(), field.c_str());
  return Ok{};
}

Status checkImageExtension(const std::string& path, const std::string& field) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".png" && ext != ".exr") return Error::inField(field, "'" + path + "' must end in .png or .exr");
  return Ok{};
}

void addDeviceFlags(CLI::App& cmd, DeviceFlags& flags) {
  cmd.add_option("--device", flags.name,
                 "Force the Vulkan device whose name contains NAME (default: $GLOBE_DEVICE, "
                 "else a discrete GPU, else lavapipe)");
  cmd.add_flag("--validate", flags.validation, "Enable the Vulkan validation layers; any message fails the command");
}

vk::DeviceOptions deviceOptions(const DeviceFlags& flags) {
  vk::DeviceOptions o;
  o.deviceName = flags.name.empty() ? vk::deviceNameFromEnvironment() : flags.name;
  const char* env = std::getenv("GLOBE_VALIDATION");
  o.validation = flags.validation || (env && std::string(env) == "1");
  return o;
}

void printDeviceChoice(const vk::Device& device) {
  std::printf("device: %s (%s; driver %s, %s)\n", device.name().c_str(), device.choice().c_str(),
              device.driverName().c_str(), device.driverInfo().c_str());
  std::fflush(stdout);
}

int validationExitCode(vk::Device& device) {
  size_t n = device.validation().count();
  if (n == 0) return kExitOk;
  // One line: the first message and how many followed.
  std::string first = device.validation().messages().front();
  printError("vulkan validation " + first + (n > 1 ? " (and " + std::to_string(n - 1) + " more)" : ""));
  return kExitFailure;
}

namespace {

// --tolerance, --texel-px and --roughness: how far the LOD refines (docs/lod.md).
void addLodOptions(CLI::App& cmd, QualityOptions& options) {
  cmd.add_option("--tolerance", options.tolerance_px,
                 "Screen error in pixels the LOD keeps within (0.05..1000; docs/lod.md; default: the preset's LOD)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            double px = 0;
            if (!CLI::detail::lexical_cast(text, px) || !(px >= kMinTolerancePx && px <= kMaxTolerancePx))
              return "must be a number of pixels in [0.05, 1000], got '" + text + "'";
            return {};
          },
          "PX"));
  cmd.add_option("--texel-px", options.texel_px,
                 "With tolerance-driven ranges and surface textures: also refine nodes whose texels would cover more "
                 "than PX pixels (0 = off, else 0.5..1000; docs/lod.md, \"Texel rule\"; default: the preset's)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            double px = 0;
            if (!CLI::detail::lexical_cast(text, px) || !(px == 0.0 || (px >= kMinTexelPx && px <= kMaxTolerancePx)))
              return "must be 0 or a number of pixels in [0.5, 1000], got '" + text + "'";
            return {};
          },
          "PX"));
  cmd.add_option("--roughness", options.roughness,
                 "With tolerance-driven ranges: on (refine rough relief further than plains and sea) or off "
                 "(one range per depth) (docs/lod.md, \"Roughness\"; default: off)")
      ->check(CLI::IsMember({"on", "off"}));
}

}  // namespace

void addQualityOptions(CLI::App& cmd, QualityOptions& options, bool withGrid) {
  if (withGrid) {
    cmd.add_option("--grid", options.gridCells,
                   "Grid cells per node side (power of two, 8..256; default: the quality preset's)")
        ->check(CLI::Range(GLOBE_PAYLOAD_MIN_CELLS, GLOBE_PAYLOAD_MAX_CELLS));
  }
  cmd.add_option("--quality", options.quality,
                 "fast, balanced or exact (docs/tradeoffs.md; default: the planet's default_quality)")
      ->check(nonEmptyValue());
  cmd.add_option(
         "--aa", options.antialiasing,
         "Anti-aliasing: none, fxaa or msaa4 (docs/rendering.md, \"Anti-aliasing\"; default: the quality preset's)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            auto aa = parseAntialiasing(text, "--aa");
            return aa ? std::string() : aa.error().message;
          },
          "AA"));
  addLodOptions(cmd, options);
  cmd.add_option("--detail-textures", options.detailTextures,
                 "On a planet with land cover: on (splat the classes' detail textures per fragment), near (only "
                 "near the camera, faded out by 200 m) or off (the classes' colours per vertex) "
                 "(docs/rendering.md, \"Land cover\"; default: the preset's)")
      ->check(CLI::IsMember({"on", "near", "off"}));
  cmd.add_option("--imagery", options.imagery,
                 "on (the surface textures from imagery tiles of their own LOD: each texel covers at most 1.5 "
                 "pixels, whatever the mesh's level) or off (each node's own texture, --normal-map-scale) "
                 "(docs/rendering.md, \"Imagery LOD\"; default: the preset's)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd.add_option("--normal-map-scale", options.normalMapScale,
                 "Surface texture texels (normal, colour, coast per pixel) per grid cell: 1, 2, 4 or 8; 0 = none, "
                 "light per vertex (docs/rendering.md, \"Surface textures\"; default: the preset's)")
      ->check(CLI::IsMember({0U, 1U, 2U, 4U, 8U}));
  cmd.add_option("--shadows", options.shadows,
                 "on (cast shadows of the relief from the sun, with surface textures) or off (docs/rendering.md, "
                 "\"Shadows\"; default: the preset's)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd.add_option("--atmosphere", options.atmosphere,
                 "With a planet's [atmosphere]: full (sky, light and aerial perspective), sky (the sky, the "
                 "terrain Lambert-lit through an analytic haze) or off (docs/rendering.md, \"Atmosphere\"; default: "
                 "the preset's)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            auto detail = parseAtmosphereDetail(text, "--atmosphere");
            return detail ? std::string() : detail.error().message;
          },
          "DETAIL"));
}

Result<TerrainSettings> terrainSettingsFromOptions(const QualityOptions& options, const PlanetDescription& planet,
                                                   double viewHeight_px) {
  auto preset = chooseQualityPreset(options.quality, planet);
  if (!preset) return preset.error();
  TerrainSettings settings = terrainSettingsFor(*preset);
  if (options.gridCells) settings.gridCells = options.gridCells;
  if (options.tolerance_px > 0) settings.ranges.tolerance_px = options.tolerance_px;
  if (options.texel_px >= 0) settings.ranges.texel_px = options.texel_px;
  if (!options.roughness.empty()) settings.ranges.roughness = options.roughness == "on";
  if (!options.detailTextures.empty()) {
    auto detail = parseDetailTextures(options.detailTextures, "--detail-textures");
    if (!detail) return detail.error();
    settings.detailTextures = *detail;
  }
  if (!options.imagery.empty()) settings.imagery = options.imagery == "on";
  if (!options.shadows.empty()) settings.shadows = options.shadows == "on";
  if (!options.antialiasing.empty()) {
    auto aa = parseAntialiasing(options.antialiasing, "--aa");
    if (!aa) return aa.error();
    settings.antialiasing = *aa;
  }
  if (options.normalMapScale != kPresetNormalMapScale) settings.normalMapScale = options.normalMapScale;
  if (!options.atmosphere.empty()) {
    auto detail = parseAtmosphereDetail(options.atmosphere, "--atmosphere");
    if (!detail) return detail.error();
    settings.atmosphere = *detail;
  }
  settings.viewHeight_px = viewHeight_px;
  if (auto s = validateTerrainSettings(settings); !s) {
    Error e = s.error();
    if (e.field == "grid_cells") e.field = "--grid";
    return e;
  }
  return settings;
}

Result<TerrainSettings> renderSettingsFromOptions(const QualityOptions& quality, const BudgetOptions& budget,
                                                  const PlanetDescription& planet, ImageSize size, bool mp4) {
  auto settings = terrainSettingsFromOptions(quality, planet, size.height);
  if (!settings) return settings.error();
  if (auto s = checkImageMemory(size, settings->antialiasing, mp4); !s) return s.error();
  if (auto s = applyBudgetOptions(budget, *settings); !s) return s.error();
  return settings;
}

void addHeightReferenceOption(CLI::App& cmd, std::string& heightRef) {
  cmd.add_option("--height-ref", heightRef,
                 "What --at's HEIGHT is measured from: ground (the terrain below the camera), or sphere / "
                 "ellipsoid (the planet's reference surface: ellipsoidal height on an ellipsoidal planet)")
      ->capture_default_str();
}

void addBudgetOptions(CLI::App& cmd, BudgetOptions& budget) {
  const FrameBudget defaults;
  cmd.add_option("--max-nodes", budget.maxNodes,
                 fmt::format("Most terrain nodes drawn per frame; beyond, coarser terrain and a warning (default {})",
                             defaults.maxDrawnNodes))
      ->check(CLI::Range(30U, 1U << 24));
  cmd.add_option("--max-triangles", budget.maxTriangles,
                 fmt::format("Most triangles drawn per frame (default {})", defaults.maxTriangles))
      ->check(CLI::Range(uint64_t{1}, uint64_t{1} << 40));
  cmd.add_option("--max-requests", budget.maxRequests,
                 fmt::format("Most payload generation requests per frame (default {})", defaults.maxRequests))
      ->check(CLI::Range(2U, 1U << 24));
  cmd.add_option("--vram-mib", budget.vram_MiB,
                 fmt::format("Payload pool budget in MiB (default {:g})", StreamingConfig{}.vramBudget_MiB))
      ->check(CLI::Range(1.0, 1048576.0));
  cmd.add_option("--imagery-mib", budget.imagery_MiB,
                 fmt::format("Imagery tiles' pool budget in MiB, with --imagery on (default {:g}; at most {} "
                             "storage-buffer bindings' worth)",
                             ImagerySettings{}.vramBudget_MiB, kImageryTilePages))
      ->check(CLI::Range(1.0, 1048576.0));
}

Status applyBudgetOptions(const BudgetOptions& budget, TerrainSettings& settings) {
  FrameBudget& b = settings.streaming.budget;
  if (budget.maxNodes) b.maxDrawnNodes = budget.maxNodes;
  if (budget.maxTriangles) b.maxTriangles = budget.maxTriangles;
  if (budget.maxRequests) b.maxRequests = budget.maxRequests;
  if (budget.vram_MiB > 0) settings.streaming.vramBudget_MiB = budget.vram_MiB;
  if (budget.imagery_MiB > 0) settings.imagerySettings.vramBudget_MiB = budget.imagery_MiB;
  if (auto s = validateTerrainSettings(settings); !s) return budgetOptionError(s.error());
  return Ok{};
}

Error budgetOptionError(Error e) {
  if (e.field == "max_triangles") e.field = "--max-triangles";
  if (e.field == "max_drawn_nodes") e.field = "--max-nodes";
  if (e.field == "max_requests") e.field = "--max-requests";
  if (e.field == "vram_budget_mib") e.field = "--vram-mib";
  if (e.field == "imagery_vram_budget_mib") e.field = "--imagery-mib";
  return e;
}

int usageError(const Error& error) {
  printError(error.format());
  return kExitUsage;
}

std::string defaultPlanetPath() { return defaultAssetPath("planets/earthlike.toml"); }

std::string defaultAssetPath(const std::string& relative) {
  return dataDirectory("GLOBE_ASSET_DIR", "assets") + "/" + relative;
}

void addSunOption(CLI::App& cmd, std::string& sun) {
  cmd.add_option("--sun", sun,
                 "Sun: AZIMUTH,ELEVATION in degrees in the sky of the camera's (first) position, azimuth "
                 "clockwise from north; default: about 55 degrees up in the south-east (north-east south "
                 "of the equator)")
      ->check(nonEmptyValue());
}

Result<glm::dvec3> sunFromOption(const std::string& sun, const glm::dvec3& position_m,
                                 const std::optional<SunAngles>& fallback) {
  if (sun.empty()) return fallback ? sunDirectionAt(position_m, *fallback) : defaultSunDirection(position_m);
  auto angles = parseSunAngles(sun, "--sun");
  if (!angles) return angles.error();
  return sunDirectionAt(position_m, *angles);
}

}  // namespace globe::cli
