#pragma once
// Notices that a planet file changed on disk, for `globe view`'s live reload. Polling (a stat() at
// most every `interval`) rather than inotify: it sees editors that replace the file by renaming a
// temporary over it (a new inode) exactly like in-place writes, costs a microsecond, and needs no
// file descriptor or thread. The stamp is modification time (ns), size and inode, so a change is
// seen even when two saves fall within the file system's timestamp resolution but change the size.
#include <chrono>
#include <cstdint>
#include <string>

namespace globe {

class PlanetFileWatcher {
 public:
  using Clock = std::chrono::steady_clock;

  // Records the file's current stamp: only later changes are reported.
  explicit PlanetFileWatcher(std::string path, Clock::duration interval = std::chrono::milliseconds(250));

  // True once per change of the stamp (including the file disappearing or reappearing), checked at
  // most once per interval.
  bool changed(Clock::time_point now);

  const std::string& path() const { return path_; }

 private:
  struct Stamp {
    bool exists = false;
    int64_t mtime_ns = 0;
    int64_t size = 0;
    uint64_t inode = 0;
    bool operator==(const Stamp&) const = default;
  };
  static Stamp stampOf(const std::string& path);

  std::string path_;
  Clock::duration interval_;
  Clock::time_point nextCheck_;
  Stamp stamp_;
};

}  // namespace globe
