#pragma once
// What file-writing tests share: a fresh, empty directory per test (named after the test and the
// process, so parallel ctest runs never collide), removed afterwards, and a whole-file reader.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace globe::testing {

class TempDir {
 public:
  // `name`: unique within the test program, e.g. "bench_report_baseline".
  explicit TempDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("globe_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string str() const { return path_.string(); }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// The whole file's bytes ("" if it cannot be read).
inline std::string readFileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace globe::testing
