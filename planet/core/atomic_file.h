#pragma once
// Writes a file so that readers never see it half-written: the content goes to a temporary file
// beside the target, which is renamed over the target only once complete. An interrupted write
// (error, crash, kill) leaves no target file and, through the destructor, no temporary either.
#include "planet/core/error.h"

#include <span>
#include <string>
#include <string_view>

namespace globe {

class AtomicFile {
 public:
  // Nothing is created until tempPath() is written by the caller.
  explicit AtomicFile(std::string targetPath);
  ~AtomicFile();  // removes the temporary unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& targetPath() const { return target_; }
  const std::string& tempPath() const { return temp_; }

  // Writes `content` to the temporary, checking every write, the fsync and the close (ENOSPC, EFBIG,
  // EIO); the Error names the target and strerror.
  Status write(std::string_view content);

  // Renames the temporary over the target.
  Status commit();

 private:
  std::string target_;
  std::string temp_;
  bool committed_ = false;
};

// Fails with a one-line Error when `path`'s directory does not exist or is not writable, so a
// command can refuse before it spends time computing an output it cannot store.
Status checkWritable(const std::string& path, const std::string& field);

// Writes `content` to `path` atomically. Every write, the fsync and the close are checked: on any
// failure (ENOSPC, EFBIG, EIO) the Error names `path` and the reason, and the old file is untouched.
Status writeFileAtomically(const std::string& path, std::string_view content, const std::string& field);

// One file of a multi-file output: its name inside the output directory and its whole content.
struct NamedContent {
  std::string name;
  std::string content;
};

// Writes every file into `dir` so that a failure changes none of them: all temporaries are written
// first, then renamed in order (so the last file's existence means the earlier ones are complete).
// On failure the existing files are untouched and no temporaries remain. The one way to write a
// multi-file output (trade.csv + pareto.svg; the bench report should use it too).
Status writeFilesAtomically(const std::string& dir, std::span<const NamedContent> files);

}  // namespace globe
