#pragma once
// The RAM tier of the out-of-core source data (docs/elevation-data.md, "Out of core"): tiles of
// kSourceTilePixels x kSourceTilePixels pixels of one level of a source's pyramid (raster_pyramid.h)
// read from disk on demand, kept under
// a byte budget and evicted least recently used. The VRAM tier is the payload pool, which holds the
// node payloads generated from them. Reads happen on the thread that asks: the source I/O thread
// (request_preparer.h) and the command-line tools. A thread marked as a frame loop
// (ScopedFrameLoopThread) never reads: a miss there returns nothing (the caller falls back to what
// lies beneath) and is counted; frameLoopWaits counts reads that would have blocked a frame and
// must stay 0.
#include "planet/core/hash.h"
#include "planet/sources/raster_pyramid.h"

#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>

namespace globe {

struct TileCacheStats {
  std::uint64_t hits = 0;               // lookups answered from RAM
  std::uint64_t reads = 0;              // tiles read and decoded from disk
  std::uint64_t coarseReads = 0;        // of which from levels >= 1 (the pyramid)
  std::uint64_t evictions = 0;          // tiles dropped for the budget
  std::uint64_t frameThreadMisses = 0;  // lookups on a frame-loop thread that found no tile
  std::uint64_t frameLoopWaits = 0;     // disk reads done on a frame-loop thread (kept at 0)
  std::size_t residentBytes = 0, peakResidentBytes = 0;
  double readSeconds = 0.0;  // time spent reading and decoding
};

class TileCache {
 public:
  explicit TileCache(std::size_t budgetBytes) : budget_(budgetBytes) {}

  // Tile (tx, ty) of `source`'s level `level` (pixels [tx * kSourceTilePixels, ...) clipped to the
  // level), read now when it is not resident, unless this is a frame-loop thread (then nullptr).
  // nullptr also when the read fails. The tile stays valid while held, evicted or not.
  std::shared_ptr<const RasterBlock> tile(const TileSource& source, int level, int tx, int ty);
  // True when the tile is resident (no read).
  bool resident(const TileSource& source, int level, int tx, int ty) const;

  void setBudget(std::size_t budgetBytes);
  TileCacheStats stats() const;

 private:
  struct Key {
    std::uint64_t source;
    std::int32_t level, tx, ty;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return std::size_t(mix64(k.source ^ (std::uint64_t(std::uint32_t(k.level)) << 56)) ^
                         (std::uint64_t(std::uint32_t(k.tx)) << 32) ^ std::uint32_t(k.ty));
    }
  };
  struct Entry {
    std::shared_ptr<const RasterBlock> block;
    std::list<Key>::iterator lru;
  };
  void evictLocked();

  mutable std::mutex mutex_;
  std::size_t budget_;
  std::list<Key> lru_;  // most recent first
  std::unordered_map<Key, Entry, KeyHash> entries_;
  mutable TileCacheStats stats_;
};

// Marks the current thread as a frame loop for its lifetime: the tile cache never reads on it.
class ScopedFrameLoopThread {
 public:
  ScopedFrameLoopThread();
  ~ScopedFrameLoopThread();
  ScopedFrameLoopThread(const ScopedFrameLoopThread&) = delete;
  ScopedFrameLoopThread& operator=(const ScopedFrameLoopThread&) = delete;

 private:
  bool previous_;
};

}  // namespace globe
