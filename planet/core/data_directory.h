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

// A per-user cache folder: $VARIABLE when set and not empty, else $XDG_CACHE_HOME/globe/NAME, else
// $HOME/.cache/globe/NAME, else the system's temporary folder's globe-NAME. Not created here.
std::string userCacheDirectory(const char* environmentVariable, const std::string& name);

}  // namespace globe
