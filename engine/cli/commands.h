#pragma once
// The subcommands of `globe`. Each registers its options on the CLI11 app and, when selected,
// sets `run` to the function that carries it out (returning the process exit code).
#include "engine/render/terrain_warnings.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <functional>
#include <string>

namespace globe::cli {

using Runner = std::function<int()>;

void addRenderCommand(CLI::App& app, Runner& run);
void addViewCommand(CLI::App& app, Runner& run);
void addPlanetCommand(CLI::App& app, Runner& run);  // globe planet check|stats|sample|export
// `commandLine`: the whole invocation, recorded in the benchmark report.
void addBenchCommand(CLI::App& app, Runner& run, const std::string& commandLine);
void addTradeCommand(CLI::App& app, Runner& run);    // globe trade: speed/accuracy sweep
void addPathCommand(CLI::App& app, Runner& run);     // globe path import|export: KML tours, CZML
void addMovieCommand(CLI::App& app, Runner& run);    // globe movie: PNG/EXR sequences, MP4
void addPhysicsCommand(CLI::App& app, Runner& run);  // globe physics: bodies on the collision meshes
void addBakeCommand(CLI::App& app, Runner& run);     // globe bake: quantized-mesh / COG terrain tiles
void addCompareCommand(CLI::App& app, Runner& run);  // globe compare: images against references

// Exit codes shared by every command.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  // the command could not do its job (device, I/O, ...)
constexpr int kExitUsage = 2;    // bad command-line values or input files

// Prints "globe: error: MESSAGE" on one line to stderr.
void printError(const std::string& message);
// Prints "globe: warning: MESSAGE" on one line to stderr: the command goes on.
void printWarning(const std::string& message);
// Prints the warnings `terrain` raised since `seen` last looked (engine/render/terrain_warnings.h).
void printNewWarnings(TerrainWarnings& seen, const Terrain& terrain);

// Milliseconds since the process started (static initialisation of the program): what "cold
// start" is measured from (docs/benchmark.md).
double millisecondsSinceProcessStart();

}  // namespace globe::cli
