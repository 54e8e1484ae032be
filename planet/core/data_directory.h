#pragma once
// Where globe's read-only data (SPIR-V, assets) lives: beside the running program, as
// PREFIX/bin/PROGRAM -> PREFIX/share/globe. The build tree has the same layout, so a build and an
// install find their data the same way and no absolute build path is compiled in.
#include <string>

namespace globe {

// PREFIX/share/globe for the running program; the current directory's share/globe if the program's
// own path cannot be read.
std::string dataDirectory();

// $VARIABLE when set and not empty, else dataDirectory() + "/" + subdirectory.
std::string dataDirectory(const char* environmentVariable, const std::string& subdirectory);

}  // namespace globe
