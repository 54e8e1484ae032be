// globe path import|export: camera paths from and to the tools people use (KML tours, CZML).
#include "commands.h"
#include "options.h"
#include "planet/core/atomic_file.h"
#include "planet/paths/camera_path_file.h"
#include "planet/paths/kml_tour.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

namespace globe::cli {

namespace {

std::string lowerExtension(const std::string& file) {
  std::string e = std::filesystem::path(file).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

struct PathFiles {
  std::string in;
  std::string out;
};

int runImport(const PathFiles& f) {
  const std::string ext = lowerExtension(f.in);
  if (ext != ".kml" && ext != ".czml")
    return usageError({"", 0, 0, "FILE", "import reads .kml (Google Earth tour) or .czml files, got '" + f.in + "'"});
  if (lowerExtension(f.out) != ".path") return usageError({"", 0, 0, "--out", "must name a .path file"});
  if (auto s = checkWritable(f.out, "--out"); !s) return usageError(s.error());
  auto path = loadCameraPath(f.in);
  if (!path) return usageError(path.error());
  if (auto s = saveCameraPath(f.out, *path); !s) {
    printError(s.error().format());
    return kExitFailure;
  }
  std::printf("wrote %s (%zu keyframes, %.3f s)\n", f.out.c_str(), path->keyframes().size(), path->duration_s());
  return kExitOk;
}

int runExport(const PathFiles& f) {
  if (lowerExtension(f.out) != ".kml") return usageError({"", 0, 0, "--out", "must name a .kml file"});
  if (auto s = checkWritable(f.out, "--out"); !s) return usageError(s.error());
  auto path = loadCameraPath(f.in);
  if (!path) return usageError(path.error());
  const std::string name = std::filesystem::path(f.in).stem().string();
  if (auto s = writeFileAtomically(f.out, formatKmlTour(*path, name), "--out"); !s) {
    printError(s.error().format());
    return kExitFailure;
  }
  std::printf("wrote %s (a gx:Tour of %zu views, %.3f s)\n", f.out.c_str(), path->keyframes().size(),
              path->duration_s());
  return kExitOk;
}

}  // namespace

void addPathCommand(CLI::App& app, Runner& run) {
  CLI::App* cmd = app.add_subcommand("path", "Camera paths: import KML tours and CZML, export KML tours");
  cmd->require_subcommand(1);
  auto imp = std::make_shared<PathFiles>();
  CLI::App* importCmd = cmd->add_subcommand(
      "import", "Convert a Google Earth tour (.kml, gx:Tour) or a CZML document (.czml) to a .path file");
  importCmd->add_option("FILE", imp->in, "The .kml or .czml file")->required();
  importCmd->add_option("--out", imp->out, "The .path file to write")->required();
  importCmd->callback([imp, &run] { run = [imp] { return runImport(*imp); }; });
  auto exp = std::make_shared<PathFiles>();
  CLI::App* exportCmd =
      cmd->add_subcommand("export", "Write a camera path (.path, .kml or .czml) as a Google Earth tour (.kml)");
  exportCmd->add_option("FILE", exp->in, "The camera path")->required();
  exportCmd->add_option("--out", exp->out, "The .kml file to write")->required();
  exportCmd->callback([exp, &run] { run = [exp] { return runExport(*exp); }; });
}

}  // namespace globe::cli
