#include "options.h"

#include "commands.h"
#include "planet/core/data_directory.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace globe::cli {

Result<ImageSize> parseSize(const std::string& text, const std::string& field) {
  unsigned w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%u%c%u%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') ||
      text.find_first_not_of("0123456789xX") != std::string::npos)
    return Error::inField(field, "expected WxH (for example 1280x720), got '" + text + "'");
  if (w < 16 || h < 16 || w > 16384 || h > 16384)
    return Error::inField(field, "width and height must be within [16, 16384] pixels, got '" + text + "'");
  return ImageSize{w, h};
}

Status checkOutputDirectory(const std::string& dir, const std::string& field) {
  std::filesystem::path path(dir);
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_directory(path, ec))
    return Error::inField(field, "'" + dir + "' exists and is not a directory");
  std::filesystem::path parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(parent, ec))
    return Error::inField(field, "directory '" + parent.string() + "' does not exist");
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

int validationExitCode(vk::Device& device) {
  size_t n = device.validation().count();
  if (n == 0) return kExitOk;
  // One line: the first message and how many followed.
  std::string first = device.validation().messages().front();
  printError("vulkan validation " + first + (n > 1 ? " (and " + std::to_string(n - 1) + " more)" : ""));
  return kExitFailure;
}

Result<TerrainSettings> terrainSettingsFromOptions(const std::string& quality, uint32_t gridCells,
                                                   const PlanetDescription& planet) {
  auto preset = chooseQualityPreset(quality, planet);
  if (!preset) return preset.error();
  TerrainSettings settings = terrainSettingsFor(*preset);
  if (gridCells) settings.gridCells = gridCells;
  if (auto s = validateTerrainSettings(settings); !s) {
    Error e = s.error();
    if (e.field == "grid_cells") e.field = "--grid";
    return e;
  }
  return settings;
}

int usageError(const Error& error) {
  printError(error.format());
  return kExitUsage;
}

std::string defaultPlanetPath() { return defaultAssetPath("planets/earthlike.toml"); }

std::string defaultAssetPath(const std::string& relative) {
  return dataDirectory("GLOBE_ASSET_DIR", "assets") + "/" + relative;
}

}  // namespace globe::cli
