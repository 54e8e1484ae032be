#include "planet/core/atomic_file.h"

#include "planet/core/fault_injection.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

namespace globe {

namespace fs = std::filesystem;

AtomicFile::AtomicFile(std::string targetPath) : target_(std::move(targetPath)) {
  fs::path p(target_);
  temp_ = (p.parent_path() / ("." + p.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_.c_str());
}

Status AtomicFile::commit() {
  if (std::rename(temp_.c_str(), target_.c_str()) != 0)
    return Error::inFile(target_, std::string("cannot write: ") + std::strerror(errno));
  committed_ = true;
  return Ok{};
}

Status checkCreatableDirectory(const std::string& dir, const std::string& field) {
  std::error_code ec;
  fs::path existing = dir.empty() ? fs::path(".") : fs::path(dir);
  while (!fs::exists(existing, ec) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!fs::exists(existing, ec)) existing = ".";
  if (!fs::is_directory(existing, ec)) return Error::inField(field, "'" + existing.string() + "' is not a directory");
  if (::access(existing.c_str(), W_OK) != 0)
    return Error::inField(field, "directory '" + existing.string() + "' is not writable");
  return Ok{};
}

Status checkWritable(const std::string& path, const std::string& field) {
  fs::path p(path);
  if (p.filename().empty()) return Error::inField(field, "'" + path + "' is a directory, expected a file name");
  if (auto s = checkCreatableDirectory(p.parent_path().string(), field); !s) return s;
  std::error_code ec;
  if (fs::is_directory(p, ec)) return Error::inField(field, "'" + path + "' is a directory, expected a file name");
  return Ok{};
}

Status makeParentDirectories(const std::string& target) {
  fs::path dir = fs::path(target).parent_path();
  std::error_code ec;
  if (dir.empty() || fs::is_directory(dir, ec)) return Ok{};
  fs::create_directories(dir, ec);
  if (ec) return Error::inFile(target, "cannot create directory '" + dir.string() + "': " + ec.message());
  return Ok{};
}

CheckedFileWriter::CheckedFileWriter(const std::string& path, std::string errorPath, std::string field)
    : errorPath_(std::move(errorPath)), field_(std::move(field)) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) fail();
}

CheckedFileWriter::~CheckedFileWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void CheckedFileWriter::fail() {
  if (error_.empty()) error_ = std::string("cannot write: ") + std::strerror(errno);
}

bool CheckedFileWriter::write(std::string_view bytes) {
  if (failed()) return false;
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      fail();
      return false;
    }
    bytes.remove_prefix(static_cast<size_t>(n));  // a short write: write the rest
    position_ += static_cast<uint64_t>(n);
  }
  return true;
}

bool CheckedFileWriter::seek(uint64_t offset) {
  if (failed()) return false;
  if (::lseek(fd_, static_cast<off_t>(offset), SEEK_SET) < 0) {
    fail();
    return false;
  }
  position_ = offset;
  return true;
}

Status CheckedFileWriter::finish() {
  // A full disk (ENOSPC), a file size limit (EFBIG) or a failing close must not leave a truncated
  // file that a commit would rename over a good one.
  if (fd_ >= 0) {
    if (!failed() && (injectFault("fsync") ? (errno = EIO, true) : ::fsync(fd_) != 0)) fail();
    if (::close(fd_) != 0) fail();
    fd_ = -1;
  }
  if (failed()) return Error::inFileField(errorPath_, field_, error_);
  return Ok{};
}

namespace {

Status writeAll(const std::string& tempPath, std::string_view content, const std::string& target,
                const std::string& field) {
  CheckedFileWriter file(tempPath, target, field);
  file.write(content);
  return file.finish();
}

}  // namespace

Status AtomicFile::write(std::string_view content) {
  if (auto s = makeParentDirectories(target_); !s) return s;
  return writeAll(temp_, content, target_, "");
}

Status AtomicFile::write(const std::function<void(CheckedFileWriter&)>& produce) {
  if (auto s = makeParentDirectories(target_); !s) return s;
  CheckedFileWriter file(temp_, target_);
  produce(file);
  return file.finish();
}

Status writeFileAtomically(const std::string& path, std::string_view content, const std::string& field) {
  if (auto s = checkWritable(path, field); !s) return s;
  AtomicFile file(path);
  if (auto s = makeParentDirectories(path); !s) return s;
  if (auto s = writeAll(file.tempPath(), content, path, field); !s) return s;
  return file.commit();
}

void removeStaleTemporaries(const std::string& targetPath) {
  const fs::path p(targetPath);
  const std::string prefix = "." + p.filename().string() + ".tmp";
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(p.parent_path().empty() ? fs::path(".") : p.parent_path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string pid = name.substr(prefix.size());
    if (pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 9) continue;
    const auto id = static_cast<pid_t>(std::stol(pid));
    if (id != ::getpid() && ::kill(id, 0) != 0 && errno == ESRCH) fs::remove(entry.path(), ec);
  }
}

Status writeFilesAtomically(const std::string& dir, std::span<const NamedContent> files) {
  std::vector<std::unique_ptr<AtomicFile>> written;
  for (const NamedContent& f : files) {
    const std::string path = (fs::path(dir) / f.name).string();
    if (auto s = checkWritable(path, ""); !s) return Error::inFile(path, s.error().message);
    removeStaleTemporaries(path);
    written.push_back(std::make_unique<AtomicFile>(path));
    if (auto s = f.produce ? written.back()->write(f.produce) : written.back()->write(f.content); !s) return s;
  }
  // The old last file goes first: a set interrupted between renames then lacks its last file instead
  // of mixing new files with an old one (a killed bench: new frames.csv beside an old report.html).
  if (!written.empty() && std::remove(written.back()->targetPath().c_str()) != 0 && errno != ENOENT)
    return Error::inFile(written.back()->targetPath(), std::string("cannot replace: ") + std::strerror(errno));
  for (auto& file : written)
    if (auto s = file->commit(); !s) return s;
  return Ok{};
}

}  // namespace globe
