#include "planet/streaming/request_preparer.h"

#include "planet/sources/source_mosaic.h"
#include "planet/streaming/payload_reference.h"
#include "planet/surface/surface_overlay.h"

#include "planet/core/parallel_for.h"

#include <algorithm>
#include <atomic>

namespace globe {

std::vector<glm::dvec4> sourceTermsAt(const ElevationModel& model, std::span<const glm::dvec3> directions,
                                      unsigned threads, double sampleSpacing_m) {
  std::vector<glm::dvec4> terms;
  if (model.sources() == nullptr) return terms;
  terms.resize(directions.size());
  std::atomic<bool> any{false};
  parallelFor(directions.size(), 1024, threads, [&](std::size_t begin, std::size_t end) {
    bool touched = false;
    for (std::size_t k = begin; k < end; ++k) {
      const SourceTerm t = model.sourceTerm(directions[k], sampleSpacing_m);
      terms[k] = {t.height_m, t.weight, t.hole, t.detailBound_m};
      touched = touched || t.weight > 0.0 || t.hole > 0.0;
    }
    if (touched) any = true;
  });
  if (!any) terms.clear();
  return terms;
}

std::vector<glm::dvec4> sourceTermsForJob(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                                          std::span<const glm::dvec3> samples) {
  if (model.sources() == nullptr) return {};
  // The pyramid level whose pixels match the payload's spacing (the CPU reference reads the same).
  return sourceTermsAt(model, samples, 1, payloadSampleSpacing_m(job, cells, model.radius_m()));
}

namespace {

// Lattice points a side of the blocks whose vector queries are skipped together (a line a texel or two
// wide crosses few of a node's blocks).
constexpr int kOverlayBlock = 8;

// Per block of kOverlayBlock x kOverlayBlock points of a `side` x `side` lattice (row by row), whether
// some vector feature may reach its texels of `texel_m` metres (`direction(a, b)`: point (a, b)'s unit
// direction): the box of its four corners, with vectorsMayTouch's margin of the antialiasing filter and
// three texels, holds the block at these sizes, so a block ruled out would have drawn no vector.
template <class Direction>
std::vector<bool> blocksVectorsMayTouch(const SurfaceOverlay& overlay, int side, double texel_m,
                                        Direction&& direction) {
  const int perSide = (side + kOverlayBlock - 1) / kOverlayBlock;
  std::vector<bool> touched(std::size_t(perSide) * perSide);
  for (int bb = 0; bb < perSide; ++bb)
    for (int ba = 0; ba < perSide; ++ba) {
      const int a0 = ba * kOverlayBlock, b0 = bb * kOverlayBlock;
      const int a1 = std::min(a0 + kOverlayBlock - 1, side - 1), b1 = std::min(b0 + kOverlayBlock - 1, side - 1);
      const glm::dvec3 corners[4] = {direction(a0, b0), direction(a1, b0), direction(a0, b1), direction(a1, b1)};
      touched[std::size_t(bb) * perSide + ba] = overlay.vectorsMayTouch(corners, texel_m);
    }
  return touched;
}

}  // namespace

std::vector<std::uint32_t> overlayColoursForJob(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                                                uint32_t mapScale, std::span<const glm::dvec3> samples) {
  const SurfaceOverlay* overlay = model.overlay();
  if (overlay == nullptr) return {};
  const uint32_t m = cells * mapScale;
  const double sample_m = payloadSampleSpacing_m(job, cells, model.radius_m());
  const double texel_m = m > 0 ? payloadSampleSpacing_m(job, m, model.radius_m()) : sample_m;
  const bool vectors = overlay->vectorsMayTouch(samples, std::max(sample_m, 2.0 * texel_m));
  // The colour words, then the vectors' own (payload_layout.h).
  std::vector<std::uint32_t> words, vectorWords;
  words.reserve(GLOBE_PAYLOAD_OVERLAY_WORDS(cells, m));
  vectorWords.reserve(GLOBE_PAYLOAD_OVERLAY_POINTS(cells, m));
  bool any = false;
  auto add = [&](const glm::dvec3& dir, double spacing_m, bool texel) {
    const SurfaceColour c = overlay->colourAt(dir, spacing_m, vectors && texel);
    words.push_back(packOverlayColour(c.land));
    vectorWords.push_back(packOverlayColour(c.vectors));
    any = any || (words.back() >> 24) != 0;
  };
  // The vertices take the imagery alone: vectors are drawn into the surface textures, where a line keeps
  // its width; a vertex would widen it to its cell and smear it over the triangles (overlaidAlbedo).
  for (const glm::dvec3& dir : samples) add(dir, sample_m, false);
  // The surface grids as the kernel's scratch holds them: mip 0's lattice points 2g - 5, mip 1's 4g - 6.
  if (m > 0) {
    const struct {
      int side, stride, offset;
      double texel_m;
    } grids[2] = {{int(GLOBE_SURFACE_GRID0_SIDE(m)), 2, 5, texel_m},
                  {int(GLOBE_SURFACE_GRID1_SIDE(m)), 4, 6, 2.0 * texel_m}};
    for (const auto& g : grids) {
      auto direction = [&](int a, int b) {
        return payloadSampleDirection(job, 2 * m, g.stride * a - g.offset, g.stride * b - g.offset);
      };
      const std::vector<bool> blocks =
          vectors ? blocksVectorsMayTouch(*overlay, g.side, g.texel_m, direction) : std::vector<bool>();
      const int perSide = (g.side + kOverlayBlock - 1) / kOverlayBlock;
      for (int b = 0; b < g.side; ++b)
        for (int a = 0; a < g.side; ++a)
          add(direction(a, b), g.texel_m, vectors && blocks[(b / kOverlayBlock) * perSide + a / kOverlayBlock]);
    }
  }
  if (!any) return {};
  words.insert(words.end(), vectorWords.begin(), vectorWords.end());
  return words;
}

bool overlayNeedsColourLayer(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                             std::span<const std::uint32_t> words) {
  const SurfaceOverlay* overlay = model.overlay();
  if (overlay == nullptr || words.empty()) return false;
  // The vectors' own words, the second half (their coverage in the top byte).
  const auto vectorWords = words.subspan(words.size() / 2);
  if (std::any_of(vectorWords.begin(), vectorWords.end(), [](std::uint32_t w) { return (w >> 24) != 0; })) return true;
  const double cell_m = payloadSampleSpacing_m(job, cells, model.radius_m());
  const auto& layers = overlay->imagery().layers();
  return std::any_of(layers.begin(), layers.end(),
                     [&](const ImageryLayer& l) { return l.facts().pixel_size_m < 2.0 * cell_m; });
}

double sourceDetailPad_m(const std::vector<glm::dvec4>& terms) {
  double pad = 0.0;
  for (const glm::dvec4& t : terms) pad = std::max(pad, t.w);
  return pad;
}

SourceRequestPreparer::SourceRequestPreparer(const ElevationModel& model, uint32_t cells, bool waterSurface,
                                             uint32_t mapScale)
    : model_(model), cells_(cells), waterSurface_(waterSurface), mapScale_(mapScale), thread_([this] { run(); }) {}

SourceRequestPreparer::~SourceRequestPreparer() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void SourceRequestPreparer::submit(std::span<const GenerationJob> requests) {
  if (requests.empty()) return;
  const auto now = std::chrono::steady_clock::now();
  {
    std::lock_guard lock(mutex_);
    for (const GenerationJob& r : requests) queued_.push_back(PreparedRequest{r, {}, {}, {}, now});
  }
  wake_.notify_one();
}

void SourceRequestPreparer::takeReady(std::vector<PreparedRequest>& out, std::size_t maxCount) {
  std::lock_guard lock(mutex_);
  while (!ready_.empty() && maxCount-- > 0) {
    out.push_back(std::move(ready_.front()));
    ready_.pop_front();
  }
}

void SourceRequestPreparer::waitUntilIdle() {
  std::unique_lock lock(mutex_);
  ++idleWaits_;
  idle_.wait(lock, [this] { return queued_.empty() && working_ == 0; });
}

std::size_t SourceRequestPreparer::pending() const {
  std::lock_guard lock(mutex_);
  return queued_.size() + working_ + ready_.size();
}

std::uint64_t SourceRequestPreparer::prepared() const {
  std::lock_guard lock(mutex_);
  return prepared_;
}

std::uint64_t SourceRequestPreparer::idleWaits() const {
  std::lock_guard lock(mutex_);
  return idleWaits_;
}

void SourceRequestPreparer::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || !queued_.empty(); });
    if (stop_) return;
    PreparedRequest r = std::move(queued_.front());
    queued_.pop_front();
    ++working_;
    lock.unlock();
    // The tile reads happen in here, on this thread.
    r.job = makePayloadJob(r.request.node, r.request.slot, model_, waterSurface_);
    const std::vector<glm::dvec3> samples = payloadSampleDirections(r.job, cells_);
    r.terms = sourceTermsForJob(model_, r.job, cells_, samples);
    r.overlay = overlayColoursForJob(model_, r.job, cells_, mapScale_, samples);
    r.colourLayer = overlayNeedsColourLayer(model_, r.job, cells_, r.overlay);
    lock.lock();
    --working_;
    ++prepared_;
    ready_.push_back(std::move(r));
    if (queued_.empty() && working_ == 0) idle_.notify_all();
  }
}

}  // namespace globe
