#pragma once
// Reads a user-named input file (planet, camera path, input script, bench summary) whole, refusing
// what is not a regular file or is too large, so hostile input neither blocks nor exhausts memory.
#include "planet/core/error.h"

#include <cstddef>
#include <string>

namespace globe {

// Planet files, camera paths and scripts are hand-written text: 16 MiB is far above any real one.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{16} << 20;

// The content of `path`. A FIFO, device, socket or directory is an Error naming the file (the file
// is opened non-blocking, so a FIFO without a writer never blocks); so is a file over `maxBytes`.
// `what` names the file's role in messages ("planet file", "camera path file").
Result<std::string> readInputFile(const std::string& path, const std::string& what,
                                  std::size_t maxBytes = kMaxInputFileBytes);

// The same kind check without reading: `path` must exist and be a regular file (or, when
// `directoryToo`, a directory). stat() only, so a FIFO never blocks. For inputs read by a library
// (GDAL) rather than by readInputFile.
Status checkInputFileKind(const std::string& path, const std::string& what, bool directoryToo = false);

}  // namespace globe
