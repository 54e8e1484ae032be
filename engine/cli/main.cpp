// globe: the user-facing command line.
#include "commands.h"
#include "engine/vk/vk_check.h"
#include "planet/core/error.h"
#include "planet/gdal/gdal_readers.h"

#include <cstdio>
#include <exception>
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace globe::cli {

namespace {
// Initialised before main(), after the dynamic loader: the closest the program gets to its start.
const std::chrono::steady_clock::time_point kProcessStart = std::chrono::steady_clock::now();
}  // namespace

double millisecondsSinceProcessStart() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - kProcessStart).count();
}

namespace {
// One line whatever the message holds: line breaks become spaces, other control characters and
// bytes that are not UTF-8 (echoed from hostile input) \xNN.
void printLine(const char* kind, const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "globe: %s: %s\n", kind, escapeControlCharacters(line).c_str());
}
}  // namespace

void printError(const std::string& message) { printLine("error", message); }

void printWarning(const std::string& message) { printLine("warning", message); }

void printNewWarnings(TerrainWarnings& seen, const Terrain& terrain) {
  for (const std::string& warning : seen.takeNew(terrain)) printWarning(warning);
}

// glibc returns freed heap tops to the system (trim, and mmap for blocks over 128 KiB), so a driver
// that allocates and frees the same large buffers every draw (lavapipe's vertex outputs) takes
// fresh pages, and a page fault each, every frame: 8-11 % of the frame near the ground, where ~400
// nodes are drawn (docs/rendering.md, "Frame time"). Kept instead: the peak is the peak anyway.
void keepFreedMemory() {
#ifdef __GLIBC__
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TOP_PAD, 16 << 20);
#endif
}

}  // namespace globe::cli

int main(int argc, char** argv) {
  using namespace globe::cli;
  keepFreedMemory();
  globe::installGdalReaders();  // planet files' real rasters and vector layers
  CLI::App app{
      "globe: a planetary-scale globe engine (Vulkan).\n"
      "Set GLOBE_DEVICE=NAME (or --device) to force a Vulkan device by name."};
  app.set_version_flag("--version", std::string("globe ") + GLOBE_VERSION);
  app.require_subcommand(0, 1);
  Runner run;
  addRenderCommand(app, run);
#ifdef GLOBE_HAS_VIEWER
  addViewCommand(app, run);
#endif
  addPlanetCommand(app, run);
  std::string commandLine;
  for (int i = 0; i < argc; ++i) commandLine += (i ? " " : "") + std::string(argv[i]);
  addBenchCommand(app, run, commandLine);
  addTradeCommand(app, run);
  addPathCommand(app, run);
  addMovieCommand(app, run);
  addBakeCommand(app, run);
  addPhysicsCommand(app, run);
  addCompareCommand(app, run);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    printError(e.what());
    return kExitUsage;
  }
  if (!run) {
    std::fputs(app.help().c_str(), stdout);
    return kExitOk;
  }
  try {
    return run();
  } catch (const globe::vk::VulkanError& e) {
    // A lost device (driver reset, GPU hang, unplugged eGPU) ends the command: nothing can be
    // recovered on it, and outputs are written only when complete, so none is half-written.
    if (e.result() == VK_ERROR_DEVICE_LOST)
      printError(std::string("the Vulkan device was lost (") + e.what() + "): stopped, nothing half-written");
    else
      printError(e.what());
    return kExitFailure;
  } catch (const std::exception& e) {
    printError(e.what());
    return kExitFailure;
  }
}
