#pragma once
// Writes a file so that readers never see it half-written: the content goes to a temporary file
// beside the target, which is renamed over the target only once complete. An interrupted write
// (error, crash, kill) leaves no target file and, through the destructor, no temporary either.
#include "planet/core/error.h"

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>

namespace globe {

class CheckedFileWriter;

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
  // The same, for content too large to hold at once: `produce` writes it piece by piece.
  Status write(const std::function<void(CheckedFileWriter&)>& produce);

  // Renames the temporary over the target.
  Status commit();

 private:
  std::string target_;
  std::string temp_;
  bool committed_ = false;
};

// Writes one file piece by piece, every step checked, for writers that stream and seek (OpenEXR
// writes its line-offset table last, from a destructor that swallows errors): a short write is
// continued, and the first failure (open, write, seek, fsync, close: ENOSPC, EFBIG, EIO) is kept
// and returned by finish(), naming `errorPath` and strerror. After a failure nothing more is written.
class CheckedFileWriter {
 public:
  CheckedFileWriter(const std::string& path, std::string errorPath, std::string field = "");
  ~CheckedFileWriter();  // closes the file if finish() was not called (its result is lost then)
  CheckedFileWriter(const CheckedFileWriter&) = delete;
  CheckedFileWriter& operator=(const CheckedFileWriter&) = delete;

  bool write(std::string_view bytes);  // false once any step has failed
  bool seek(uint64_t offset);          // from the start of the file
  uint64_t position() const { return position_; }
  bool failed() const { return !error_.empty(); }
  const std::string& errorMessage() const { return error_; }  // "cannot write: <strerror>"
  // fsync and close; the first failure of any step so far.
  Status finish();

 private:
  void fail();  // keeps errno's message unless a failure is already kept
  int fd_ = -1;
  uint64_t position_ = 0;
  std::string errorPath_;
  std::string field_;
  std::string error_;
};

// Fails with a one-line Error when `path` could not be written: its directory is not writable, or
// is missing and could not be made (its nearest existing ancestor is a file or not writable), so a
// command can refuse before it spends time computing an output it cannot store.
Status checkWritable(const std::string& path, const std::string& field);
// The same for a directory `dir` that is to exist: it does, or could be made.
Status checkCreatableDirectory(const std::string& dir, const std::string& field);
// Makes `target`'s missing parent directories: when an output is first written (AtomicFile::write
// and writeFileAtomically do it; writers of tempPath() call it first), never on a check, so bad
// input leaves nothing behind.
Status makeParentDirectories(const std::string& target);

// Removes the temporaries AtomicFile left for `targetPath` (".NAME.tmpPID") in runs that were
// killed (SIGKILL skips every destructor): those whose process no longer exists. A temporary of a
// run still going is kept. For command outputs, whose reruns would otherwise accumulate them.
void removeStaleTemporaries(const std::string& targetPath);

// Writes `content` to `path` atomically. Every write, the fsync and the close are checked: on any
// failure (ENOSPC, EFBIG, EIO) the Error names `path` and the reason, and the old file is untouched.
Status writeFileAtomically(const std::string& path, std::string_view content, const std::string& field);

// One file of a multi-file output: its name inside the output directory and its whole content, or,
// for a file too large to build in memory (frames.csv of an hour-long benchmark), a function that
// streams it (then `content` is unused).
struct NamedContent {
  std::string name;
  std::string content;
  std::function<void(CheckedFileWriter&)> produce;
};

// Writes every file into `dir` so that a failure changes none of them: all temporaries are written
// first, then the old last file is removed and the temporaries renamed in order, the last one last. So
// whatever stops the process (kill -9 too), the directory holds the old set, the new set, or a set
// without its last file (incomplete, never a mix of old and new files with every name present). On a
// reported failure the existing files are untouched and no temporaries remain; temporaries a killed
// earlier run left for these names are removed first (removeStaleTemporaries). The one way to write a
// multi-file output (trade.csv + pareto.svg; the bench report should use it too).
Status writeFilesAtomically(const std::string& dir, std::span<const NamedContent> files);

}  // namespace globe
