#pragma once
// Shared by the `globe planet` subcommands (planet_command.cpp, planet_export_command.cpp).
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "planet/model/planet_description.h"

namespace globe::cli {

// Loads a planet file for a command that needs a valid planet; on failure prints one line (the first
// problem, with a hint when there are more) and returns nothing.
std::optional<PlanetDescription> loadPlanetForCommand(const std::string& path);

// The worker threads of a command: --threads, default every hardware thread.
void addThreadsOption(CLI::App& cmd, unsigned& threads);
unsigned defaultThreads();

void addPlanetExportCommand(CLI::App& planet, std::function<int()>& run);
void addPlanetSampleCommand(CLI::App& planet, std::function<int()>& run);

// "FILE" argument of a planet subcommand, default the earthlike preset.
void addPlanetFileArgument(CLI::App& cmd, std::string& file);

}  // namespace globe::cli
