#include "planet/sources/tile_cache.h"

#include <algorithm>
#include <chrono>

namespace globe {
namespace {
thread_local bool tFrameLoopThread = false;
}

ScopedFrameLoopThread::ScopedFrameLoopThread() : previous_(tFrameLoopThread) { tFrameLoopThread = true; }
ScopedFrameLoopThread::~ScopedFrameLoopThread() { tFrameLoopThread = previous_; }

std::shared_ptr<const RasterBlock> TileCache::tile(const TileSource& source, int level, int tx, int ty) {
  const Key key{source.tileSourceId(), level, tx, ty};
  {
    std::lock_guard lock(mutex_);
    if (auto it = entries_.find(key); it != entries_.end()) {
      ++stats_.hits;
      lru_.splice(lru_.begin(), lru_, it->second.lru);
      return it->second.block;
    }
    if (tFrameLoopThread) {
      ++stats_.frameThreadMisses;
      return nullptr;
    }
  }
  // Read outside the lock so lookups of resident tiles go on meanwhile.
  const auto start = std::chrono::steady_clock::now();
  const PyramidLevel l = source.level(level);
  const int x0 = tx * kSourceTilePixels, y0 = ty * kSourceTilePixels;
  Result<RasterBlock> block = source.readLevel(level, x0, y0, std::min(kSourceTilePixels, l.width - x0),
                                               std::min(kSourceTilePixels, l.height - y0));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!block) return nullptr;
  auto shared = std::make_shared<const RasterBlock>(std::move(*block));
  std::lock_guard lock(mutex_);
  ++stats_.reads;
  stats_.coarseReads += level > 0;
  stats_.readSeconds += seconds;
  if (auto it = entries_.find(key); it != entries_.end()) return it->second.block;  // read twice meanwhile
  lru_.push_front(key);
  entries_.emplace(key, Entry{shared, lru_.begin()});
  stats_.residentBytes += shared->values.size() * sizeof(float);
  evictLocked();
  stats_.peakResidentBytes = std::max(stats_.peakResidentBytes, stats_.residentBytes);
  return shared;
}

bool TileCache::resident(const TileSource& source, int level, int tx, int ty) const {
  std::lock_guard lock(mutex_);
  return entries_.count(Key{source.tileSourceId(), level, tx, ty}) != 0;
}

void TileCache::evictLocked() {
  // The newest tile always stays, whatever the budget.
  while (stats_.residentBytes > budget_ && lru_.size() > 1) {
    auto it = entries_.find(lru_.back());
    stats_.residentBytes -= it->second.block->values.size() * sizeof(float);
    entries_.erase(it);
    lru_.pop_back();
    ++stats_.evictions;
  }
}

void TileCache::setBudget(std::size_t budgetBytes) {
  std::lock_guard lock(mutex_);
  budget_ = budgetBytes;
  evictLocked();
}

TileCacheStats TileCache::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

}  // namespace globe
