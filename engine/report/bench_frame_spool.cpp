#include "engine/report/bench_frame_spool.h"

#include "planet/core/fault_injection.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <type_traits>

namespace globe {

namespace {

// Rows are written as their bytes: the file is read back only by this process.
static_assert(std::is_trivially_copyable_v<BenchFrame>);

constexpr std::size_t kBufferedRows = 256;  // ~40 KB: one write per ~4 s of a 60 Hz flight

// An unnamed file in `dir`: O_TMPFILE where the file system has it, else a named one unlinked at once.
int openAnonymousFile(const std::string& dir) {
  int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0 || (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)) return fd;
  std::string name = dir + "/.frames.spool.XXXXXX";
  fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd >= 0) ::unlink(name.c_str());
  return fd;
}

}  // namespace

BenchFrameSpool::~BenchFrameSpool() {
  if (mapping_ != nullptr) ::munmap(mapping_, mappedBytes_);
  if (fd_ >= 0) ::close(fd_);
}

Status BenchFrameSpool::failure(const char* what) const {
  return Error::inFile(dir_, std::string(what) + ": " + std::strerror(errno));
}

Status BenchFrameSpool::open(const std::string& dir) {
  dir_ = dir;
  fd_ = openAnonymousFile(dir);
  if (fd_ < 0) return failure("cannot create the benchmark's row file");
  buffer_.reserve(kBufferedRows);
  return Ok{};
}

Status BenchFrameSpool::flush() {
  const char* bytes = reinterpret_cast<const char*>(buffer_.data());
  std::size_t left = buffer_.size() * sizeof(BenchFrame);
  while (left > 0) {
    const ssize_t n = injectFault("write") ? (errno = ENOSPC, -1) : ::write(fd_, bytes, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return failure("cannot write the benchmark's rows");
    }
    bytes += n;  // a short write: write the rest
    left -= std::size_t(n);
  }
  buffer_.clear();
  return Ok{};
}

Status BenchFrameSpool::append(const BenchFrame& frame) {
  if (fd_ < 0 || mapping_ != nullptr) return Error::inFile(dir_, "benchmark rows appended to a closed spool");
  buffer_.push_back(frame);
  ++count_;
  if (buffer_.size() < kBufferedRows) return Ok{};
  return flush();
}

Result<std::span<const BenchFrame>> BenchFrameSpool::rows() {
  if (fd_ < 0) return Error::inFile(dir_, "benchmark rows read from a spool never opened");
  if (count_ == 0) return std::span<const BenchFrame>();
  if (mapping_ == nullptr) {
    if (auto s = flush(); !s) return s.error();
    mappedBytes_ = count_ * sizeof(BenchFrame);
    void* p = ::mmap(nullptr, mappedBytes_, PROT_READ, MAP_PRIVATE, fd_, 0);
    if (p == MAP_FAILED) return failure("cannot map the benchmark's rows").error();
    mapping_ = p;
  }
  return std::span<const BenchFrame>(static_cast<const BenchFrame*>(mapping_), count_);
}

}  // namespace globe
