#include "planet/core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace globe {

namespace {

const char* fileKind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Closes the descriptor on every return path.
struct FileDescriptor {
  int fd;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

std::string mib(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

}  // namespace

Status checkInputFileKind(const std::string& path, const std::string& what, bool directoryToo) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return Error::inFile(path, "cannot open " + what + ": " + std::strerror(errno));
  if (S_ISREG(info.st_mode) || (directoryToo && S_ISDIR(info.st_mode))) return Ok{};
  return Error::inFile(path, "cannot read " + what + ": it is " + fileKind(info.st_mode));
}

Result<std::string> readInputFile(const std::string& path, const std::string& what, std::size_t maxBytes) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever.
  FileDescriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) return Error::inFile(path, "cannot open " + what + ": " + std::strerror(errno));
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) return Error::inFile(path, "cannot read " + what + ": " + std::strerror(errno));
  if (!S_ISREG(info.st_mode)) return Error::inFile(path, "cannot read " + what + ": it is " + fileKind(info.st_mode));
  if (static_cast<std::size_t>(info.st_size) > maxBytes)
    return Error::inFile(path, what + " is larger than the limit of " + mib(maxBytes));
  std::string content;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return Error::inFile(path, "cannot read " + what + ": " + std::strerror(errno));
    if (n == 0) break;
    // The size is checked again while reading: the file may grow after fstat.
    if (content.size() + static_cast<std::size_t>(n) > maxBytes)
      return Error::inFile(path, what + " is larger than the limit of " + mib(maxBytes));
    content.append(buffer, static_cast<std::size_t>(n));
  }
  return content;
}

}  // namespace globe
