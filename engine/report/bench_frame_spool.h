#pragma once
// The benchmark's rows while it flies: appended to an anonymous file in the output directory, so
// the process's memory does not grow with the number of frames (an hour at 60 Hz is 216,000 rows),
// then mapped read-only for the report. The file has no name (O_TMPFILE, or unlinked at once), so
// no exit — error, signal, SIGKILL — leaves it behind.
#include "engine/report/bench_report.h"
#include "planet/core/error.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace globe {

class BenchFrameSpool {
 public:
  // Nothing is opened until open() succeeds.
  BenchFrameSpool() = default;
  ~BenchFrameSpool();
  BenchFrameSpool(const BenchFrameSpool&) = delete;
  BenchFrameSpool& operator=(const BenchFrameSpool&) = delete;

  // Creates the anonymous file in `dir` (which must exist); errors name `dir` and strerror.
  Status open(const std::string& dir);

  // Appends one row (buffered; every write checked: a full disk is an Error naming the directory).
  Status append(const BenchFrame& frame);
  std::size_t size() const { return count_; }

  // Flushes and maps every row appended, in order. The span lives as long as the spool; append()
  // must not be called after.
  Result<std::span<const BenchFrame>> rows();

 private:
  Status flush();
  Status failure(const char* what) const;

  std::string dir_;
  int fd_ = -1;
  std::vector<BenchFrame> buffer_;  // rows not yet written, at most kBufferedRows
  std::size_t count_ = 0;
  void* mapping_ = nullptr;
  std::size_t mappedBytes_ = 0;
};

}  // namespace globe
