#pragma once
// Frame-accurate movies of a camera path: frame k shows path time start + k / fps, each frame
// rendered converged (every payload it needs resident, no coarser fallback), so a frame depends only
// on its camera and the same inputs give the same frames. Output is a numbered PNG or EXR sequence
// (resumable: frames already in the directory are kept, each frame is written atomically) or one
// MP4 file (written to a temporary and renamed when complete).
#include "engine/render/terrain.h"
#include "engine/vk/device.h"
#include "planet/model/planet_description.h"
#include "planet/paths/camera_path.h"

#include <functional>
#include <string>

namespace globe {

enum class MovieFormat { png, exr, mp4 };

struct MovieSettings {
  uint32_t width = 640, height = 360;
  int fps = 30;  // isSupportedFrameRate(fps, format)
  MovieFormat format = MovieFormat::png;
  std::string out;          // a directory for png/exr, a file for mp4
  std::string description;  // what the movie is made of (path, planet, quality), kept beside a sequence
  TerrainSettings terrain;  // quality preset; sun and colour ramp are set from the path and planet
};

// A video takes the broadcast rates players expect; an image sequence (a preview, frames for
// another tool) any whole rate from 1 to kMaxSequenceFrameRate.
inline constexpr int kMovieFrameRates[] = {24, 25, 30, 50, 60};
inline constexpr int kMaxSequenceFrameRate = 1000;
bool isSupportedFrameRate(int fps, MovieFormat format);
// False for mp4 in a build without FFmpeg (GLOBE_WITH_FFMPEG=OFF, the portable bundle's).
bool isFormatBuilt(MovieFormat format);

// Frames of a path `duration_s` long at `fps`: both ends included, floor(duration * fps) + 1.
uint64_t movieFrameCount(double duration_s, int fps);
// "frame_000042.png": six digits, so names sort in frame order (more when there are more frames).
std::string movieFrameName(uint64_t frame, MovieFormat format);

struct MovieSummary {
  uint64_t frames = 0;    // in the movie
  uint64_t rendered = 0;  // by this run
  uint64_t kept = 0;      // already in the directory (resumed)
  uint64_t replayed = 0;  // rendered again but not written: the LOD state before a missing frame (LodLog)
  double seconds = 0;     // wall time of this run's rendering and writing
  std::string encoder;    // MP4 only: the libavcodec encoder used
};

// Called after each frame with (frames done, frames in the movie, the terrain that drew it: its
// warnings, e.g. a frame budget reached).
using MovieProgressFn = std::function<void(uint64_t done, uint64_t total, const Terrain& terrain)>;

// Errors: unwritable output, a directory holding another movie's frames (settings.description
// differs), encoder failures. Vulkan failures throw as everywhere.
Result<MovieSummary> renderMovie(vk::Device& device, const PlanetDescription& planet, const CameraPath& path,
                                 MovieSettings settings, const MovieProgressFn& progress = {});

}  // namespace globe
