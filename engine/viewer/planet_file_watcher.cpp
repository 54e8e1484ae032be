#include "engine/viewer/planet_file_watcher.h"

#include <sys/stat.h>

namespace globe {

PlanetFileWatcher::PlanetFileWatcher(std::string path, Clock::duration interval)
    : path_(std::move(path)), interval_(interval), nextCheck_(Clock::now() + interval), stamp_(stampOf(path_)) {}

PlanetFileWatcher::Stamp PlanetFileWatcher::stampOf(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return Stamp{};
  Stamp s;
  s.exists = true;
  s.mtime_ns = int64_t(st.st_mtim.tv_sec) * 1000000000 + int64_t(st.st_mtim.tv_nsec);
  s.size = int64_t(st.st_size);
  s.inode = uint64_t(st.st_ino);
  return s;
}

bool PlanetFileWatcher::changed(Clock::time_point now) {
  if (now < nextCheck_) return false;
  nextCheck_ = now + interval_;
  Stamp current = stampOf(path_);
  if (current == stamp_) return false;
  stamp_ = current;
  return true;
}

}  // namespace globe
