#include "planet/core/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
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

Status checkWritable(const std::string& path, const std::string& field) {
  fs::path p(path);
  if (p.filename().empty()) return Error::inField(field, "'" + path + "' is a directory, expected a file name");
  fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return Error::inField(field, "directory '" + dir.string() + "' does not exist");
  if (::access(dir.c_str(), W_OK) != 0)
    return Error::inField(field, "directory '" + dir.string() + "' is not writable");
  if (fs::is_directory(p, ec)) return Error::inField(field, "'" + path + "' is a directory, expected a file name");
  return Ok{};
}

Status writeFileAtomically(const std::string& path, const std::string& content, const std::string& field) {
  if (auto s = checkWritable(path, field); !s) return s;
  AtomicFile file(path);
  {
    std::ofstream out(file.tempPath(), std::ios::binary);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) return Error::inFileField(path, field, "write failed");
  }
  return file.commit();
}

Status writeFilesAtomically(const std::string& dir, std::span<const NamedContent> files) {
  std::vector<std::unique_ptr<AtomicFile>> written;
  for (const NamedContent& f : files) {
    const std::string path = (fs::path(dir) / f.name).string();
    if (auto s = checkWritable(path, ""); !s) return Error::inFile(path, s.error().message);
    written.push_back(std::make_unique<AtomicFile>(path));
    std::ofstream out(written.back()->tempPath(), std::ios::binary);
    out.write(f.content.data(), static_cast<std::streamsize>(f.content.size()));
    out.flush();
    if (!out) return Error::inFile(path, "cannot write");
  }
  for (auto& file : written)
    if (auto s = file->commit(); !s) return s;
  return Ok{};
}

}  // namespace globe
