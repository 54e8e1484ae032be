#pragma once
// The source I/O thread (docs/elevation-data.md, "Out of core"): for each generation request of a
// planet with sources or imagery it reads and decodes the source tiles the node needs (through the
// tile cache: disk -> RAM), resolves the mosaic at every payload sample and hands back the job (its
// centre on the mosaicked surface) with the samples' source terms and the overlay's colours, which
// the GPU generator uploads with the job (RAM -> VRAM). Requests are prepared in the order they came, which is the
// payload pool's priority order (visible, then prefetch along the view and the next level, nearest first;
// planet/streaming/payload_pool.h) and bounded by its in-flight cap. The frame thread only ever
// queues and takes with short locks; it never waits for a read (frameLoopWaits stays 0); until a
// node's data arrives the pool keeps drawing its parent.
#include "planet/model/elevation_model.h"
#include "planet/streaming/payload_generator.h"
#include "shaders/include/payload_layout.h"

#include <glm/vec4.hpp>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

namespace globe {

struct PreparedRequest {
  GenerationJob request;
  gpu::PayloadJob job{};          // slot = request.slot; sourceBase is the uploader's to set
  std::vector<glm::dvec4> terms;  // S * S (height_m, weight, hole, 0), or empty: no source touches it
  // GLOBE_PAYLOAD_OVERLAY_POINTS packed overlay colours (payload_layout.h), or empty: no imagery here.
  std::vector<std::uint32_t> overlay;
  std::chrono::steady_clock::time_point queued;
  // The overlay's hue varies within the node's cells (overlayNeedsColourLayer): its fragments read the
  // colour layer; elsewhere the vertices' hue does.
  bool colourLayer = false;
};

// The packed source terms dvec4(height_m, weight, hole, detail bound) at `directions` (the one way
// terms are made, for payloads and for `globe bake`'s sampler), on `threads` threads, read from the
// sources' pyramid level for `sampleSpacing_m` (0: full resolution, as `globe bake` and
// ElevationModel::elevation_m use); empty when no direction has one (weight and hole 0 everywhere).
std::vector<glm::dvec4> sourceTermsAt(const ElevationModel& model, std::span<const glm::dvec3> directions,
                                      unsigned threads = 1, double sampleSpacing_m = 0.0);

// The S * S source terms of `job` at its `samples` (payloadSampleDirections; sample (i, j) at
// (j + 1) * S + (i + 1)); empty when no sample lies in a source's box.
std::vector<glm::dvec4> sourceTermsForJob(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                                          std::span<const glm::dvec3> samples);

// The packed overlay words of `job` (GLOBE_PAYLOAD_OVERLAY_WORDS(cells, cells * mapScale): colours, then
// the vectors' own colours, at the mesh `samples` (payloadSampleDirections), then the surface grids'
// lattice), each read for its own spacing (a sample's, a
// texel's of mip 0, of mip 1: bit for bit what the parent's mip 0 reads); empty when the planet has
// no overlay or nothing of it covers the node.
std::vector<std::uint32_t> overlayColoursForJob(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                                                uint32_t mapScale, std::span<const glm::dvec3> samples);

// Whether the overlay `words` of `job` (overlayColoursForJob) vary in hue within a cell of its mesh
// of `cells` cells: some vector covers a texel, or an imagery layer's pixels are smaller than two
// cells. Otherwise the vertices' colours carry the overlay's hue as well as the texels would, and the
// node is drawn without the colour layer's fetch (a fragment stage of its own: docs/imagery.md, "Cost").
bool overlayNeedsColourLayer(const ElevationModel& model, const gpu::PayloadJob& job, uint32_t cells,
                             std::span<const std::uint32_t> words);

// How far a node's finer descendants may reach beyond its payload's radius range because of the
// amplification detail its samples do not resolve: the largest detail bound of its terms (metres;
// 0 without terms). The generator adds it to the padded range (paddedRadiusRange).
double sourceDetailPad_m(const std::vector<glm::dvec4>& terms);

class SourceRequestPreparer {
 public:
  // `model` (with sources or an overlay) must outlive the preparer.
  // `waterSurface`: the jobs are for payloads with the sea surface (makePayloadJob); `mapScale`: their
  // surface textures' (0: none), for the overlay's lattice.
  SourceRequestPreparer(const ElevationModel& model, uint32_t cells, bool waterSurface = false, uint32_t mapScale = 0);
  ~SourceRequestPreparer();
  SourceRequestPreparer(const SourceRequestPreparer&) = delete;
  SourceRequestPreparer& operator=(const SourceRequestPreparer&) = delete;

  // Queues requests for the I/O thread.
  void submit(std::span<const GenerationJob> requests);
  // Moves the prepared requests, oldest first, into `out`, at most `maxCount`.
  void takeReady(std::vector<PreparedRequest>& out, std::size_t maxCount);
  // Blocks until every queued request is prepared (warm-up rounds, converged frames, shutdown);
  // counted in idleWaits, never called by the frame loop's normal path.
  void waitUntilIdle();
  // Requests queued or being prepared, and prepared but not yet taken.
  std::size_t pending() const;

  std::uint64_t prepared() const;
  std::uint64_t idleWaits() const;

 private:
  void run();

  const ElevationModel& model_;
  uint32_t cells_;
  bool waterSurface_ = false;
  uint32_t mapScale_ = 0;
  mutable std::mutex mutex_;
  std::condition_variable wake_;  // new requests or stop
  std::condition_variable idle_;  // queue drained
  std::deque<PreparedRequest> queued_;
  std::deque<PreparedRequest> ready_;
  std::size_t working_ = 0;
  std::uint64_t prepared_ = 0, idleWaits_ = 0;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace globe
