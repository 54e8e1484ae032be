#pragma once
// Option parsing shared by the subcommands: sizes, device selection, error reporting.
#include "engine/render/antialiasing.h"
#include "engine/render/quality.h"
#include "engine/vk/device.h"
#include "planet/camera/camera.h"
#include "planet/core/error.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace globe::cli {

struct ImageSize {
  uint32_t width = 0;
  uint32_t height = 0;
};

// Image sides: 16384 is the common maxImageDimension2D of Vulkan devices.
inline constexpr std::uint64_t kMinImageSidePx = 16;
inline constexpr std::uint64_t kMaxImageSidePx = 16384;
// Host + device memory per output pixel (colour and depth targets, read-back, the float image, the
// file's encoding), peak resident memory measured at 2048x2048 and 4096x4096 on lavapipe
// (docs/reliability.md, "Image memory"): 57 bytes with --aa none, 65 with fxaa, 88 with msaa4, and
// 40 more for an MP4 (x264's frames). The cap keeps a command within a small machine's memory.
inline constexpr std::uint64_t kRenderBytesPerPixel = 60;
inline constexpr std::uint64_t kFxaaBytesPerPixel = 68;
inline constexpr std::uint64_t kMsaa4BytesPerPixel = 92;
inline constexpr std::uint64_t kMp4BytesPerPixel = 40;
inline constexpr std::uint64_t kMaxImageMemoryMiB = 4096;

// --tolerance: below 0.05 px the ranges reach the max depth everywhere; above 1000 px nothing refines.
inline constexpr double kMinTolerancePx = 0.05;
inline constexpr double kMaxTolerancePx = 1000.0;
// --texel-px: 0 turns the texel rule off; below 0.5 px the ranges reach the max depth everywhere.
inline constexpr double kMinTexelPx = 0.5;

// "WxH" with 16 <= W, H <= 16384 and W * H * kRenderBytesPerPixel within kMaxImageMemoryMiB.
Result<ImageSize> parseSize(const std::string& text, const std::string& field);
// Once the anti-aliasing is known: the image memory of `size` with it (and an MP4 encoder) within
// kMaxImageMemoryMiB, else an Error on --size naming both.
Status checkImageMemory(ImageSize size, Antialiasing aa, bool mp4);

// An output directory: made later by the command (with any missing parents: makeOutputDirectory),
// so it must be a directory or one that can be made. Errors name `field`. (Output files: checkWritable,
// planet/core/atomic_file.h; their missing directories are made when they are written.)
Status checkOutputDirectory(const std::string& dir, const std::string& field);
// Makes `dir` when missing, once the command's input is known good, and says so on stdout.
Status makeOutputDirectory(const std::string& dir, const std::string& field);

// Output files must end in .png or .exr.
Status checkImageExtension(const std::string& path, const std::string& field);

struct DeviceFlags {
  std::string name;         // --device, else $GLOBE_DEVICE
  bool validation = false;  // --validate, or $GLOBE_VALIDATION=1
};
void addDeviceFlags(CLI::App& cmd, DeviceFlags& flags);

// QualityOptions::normalMapScale without --normal-map-scale: the preset's.
inline constexpr uint32_t kPresetNormalMapScale = ~0u;
// The quality options of every rendering command.
struct QualityOptions {
  std::string quality;                              // --quality; empty: the planet's default_quality
  uint32_t gridCells = 0;                           // --grid; 0: the preset's grid
  double tolerance_px = 0;                          // --tolerance; 0: the preset's LOD (distance or tolerance ranges)
  double texel_px = -1;                             // --texel-px; < 0: the preset's (0: off)
  std::string antialiasing;                         // --aa; empty: the preset's
  uint32_t normalMapScale = kPresetNormalMapScale;  // --normal-map-scale
  std::string atmosphere;                           // --atmosphere; empty: the preset's
  std::string shadows;                              // --shadows on|off; empty: the preset's
  std::string roughness;                            // --roughness on|off; empty: off
  std::string detailTextures;                       // --detail-textures on|near|off; empty: the preset's
  std::string imagery;                              // --imagery on|off; empty: the preset's
};
// --quality, --tolerance, --texel-px, --roughness, --detail-textures, --imagery, --aa, --normal-map-scale,
// --atmosphere, --shadows and, when withGrid,
// --grid, with the same help and checks on every rendering command; read them back with terrainSettingsFromOptions.
void addQualityOptions(CLI::App& cmd, QualityOptions& options, bool withGrid = true);
vk::DeviceOptions deviceOptions(const DeviceFlags& flags);
// One stdout line: the device a command runs on and why that one (docs/getting-started.md).
void printDeviceChoice(const vk::Device& device);

// With validation on, any message makes the command fail after it has reported them.
int validationExitCode(vk::Device& device);

// Refuses an empty value of an option whose absence means "the default" (--quality ""): an empty
// value is a mistake, not a request for the default.
CLI::Validator nonEmptyValue();

// --max-nodes, --max-triangles, --max-requests (the frame budget, planet/streaming/frame_budget.h)
// --vram-mib (the payload pool) and --imagery-mib (the imagery tiles' pool): 0 or absent keeps the default.
struct BudgetOptions {
  uint32_t maxNodes = 0;
  uint64_t maxTriangles = 0;
  uint32_t maxRequests = 0;
  double vram_MiB = 0;
  double imagery_MiB = 0;
};
void addBudgetOptions(CLI::App& cmd, BudgetOptions& budget);
// --height-ref: what --at's HEIGHT is measured from (parseHeightReference checks the value).
void addHeightReferenceOption(CLI::App& cmd, std::string& heightRef);
// Applies the given budgets to `settings` and validates them; errors name the options.
Status applyBudgetOptions(const BudgetOptions& budget, TerrainSettings& settings);
// A budget error (from the settings or Terrain::create, e.g. a VRAM budget too small for the
// roots) named by its option.
Error budgetOptionError(Error error);

// The settings of --quality (empty: the planet's default_quality) with --grid and --tolerance
// applied; `viewHeight_px` is the drawn image's height (the tolerance's pixels). Errors name the options.
Result<TerrainSettings> terrainSettingsFromOptions(const QualityOptions& options, const PlanetDescription& planet,
                                                   double viewHeight_px);

// What a rendering command's options (render, view, bench, movie) make of the planet's terrain:
// terrainSettingsFromOptions for an image of `size`, its memory with the chosen anti-aliasing
// checked (checkImageMemory; `mp4`: with an MP4 encoder's frames), then the budgets applied
// (applyBudgetOptions). Errors name the options.
Result<TerrainSettings> renderSettingsFromOptions(const QualityOptions& quality, const BudgetOptions& budget,
                                                  const PlanetDescription& planet, ImageSize size, bool mp4 = false);

// --sun AZIMUTH,ELEVATION (degrees, where the camera starts): empty keeps the default sun.
void addSunOption(CLI::App& cmd, std::string& sun);
// The sun direction for a camera at `position_m`: --sun's angles there, else `fallback`'s (a camera
// path's first keyframe's), else defaultSunDirection. Errors name --sun.
Result<glm::dvec3> sunFromOption(const std::string& sun, const glm::dvec3& position_m,
                                 const std::optional<SunAngles>& fallback = std::nullopt);

// Prints the error and returns kExitUsage.
int usageError(const Error& error);

// The planet every command uses without --planet: planets/earthlike.toml under the asset directory,
// so `globe` works from any working directory.
std::string defaultPlanetPath();
// A file under the asset directory: $GLOBE_ASSET_DIR, else share/globe/assets beside the program
// (planet/core/data_directory.h; in the build tree a link to the source tree's assets/).
std::string defaultAssetPath(const std::string& relative);

}  // namespace globe::cli
