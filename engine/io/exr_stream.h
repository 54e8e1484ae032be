#pragma once
// OpenEXR output through the checked writer (planet/core/atomic_file.h): Imf::OutputFile's own file
// stream loses the errors of its last buffered write and of the line-offset table it writes from
// its destructor, and never syncs. Write the EXR through this stream, destroy the OutputFile, then
// finish(): every write, the fsync and the close are checked, like the PNG path.
#include "planet/core/atomic_file.h"

#include <ImfIO.h>

#include <string>

namespace globe {

class CheckedExrStream final : public Imf::OStream {
 public:
  // Writes `path` (usually an AtomicFile's temporary); errors name `errorPath`.
  CheckedExrStream(const std::string& path, const std::string& errorPath);

  // Throws Iex::IoExc on the first failure, so OpenEXR stops writing.
  void write(const char c[], int n) override;
  uint64_t tellp() override { return file_.position(); }
  void seekp(uint64_t pos) override;

  // After the Imf::OutputFile is gone: fsync and close, or the first failure of any step.
  Status finish() { return file_.finish(); }

 private:
  CheckedFileWriter file_;
};

}  // namespace globe
