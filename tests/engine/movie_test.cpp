// Movies of camera paths (engine/movie): the MP4 writer's files read back with libavformat have
// the frames, size and duration written; a PNG sequence is deterministic (two runs, identical
// bytes) and resumes (a deleted frame is the only one rendered again, identically).
#include "engine/movie/movie_info.h"
#include "engine/movie/movie_renderer.h"
#include "engine/movie/mp4_writer.h"
#include "engine/render/quality.h"
#include "planet/paths/camera_path_file.h"
#include "tests/support/gpu_test.h"

#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <malloc.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace globe {
namespace {

namespace fs = std::filesystem;
using testing::readFileBytes;
using testing::TempDir;

// Ten frames of WxH fading to red over a texture that moves (flat frames would leave the encoder's
// motion search and rate control nothing to decide), encoded to `file`; returns the encoder's
// description.
std::string writeGradient(const std::string& file, uint32_t width = 64, uint32_t height = 48) {
  auto writer = Mp4Writer::open(file, width, height, 30);
  EXPECT_TRUE(writer.ok()) << writer.error().format();
  if (!writer) return "";
  for (int k = 0; k < 10; ++k) {
    ImageRgba image{width, height, std::vector<float>(std::size_t(width) * height * 4, 0.0f), {}};
    for (std::size_t p = 0; p < std::size_t(width) * height; ++p) {
      const double x = double(p % width) + 3.0 * k, y = double(p / width) + 1.0 * k;
      image.rgba[p * 4 + 0] = float(k) / 10.0f;
      image.rgba[p * 4 + 1] = float(0.5 + 0.5 * std::sin(x * 0.07) * std::cos(y * 0.05 + x * 0.01));
      image.rgba[p * 4 + 2] = float(0.5 + 0.25 * std::sin(x * 0.31 + y * 0.17) + 0.25 * std::sin(y * 0.9));
    }
    EXPECT_TRUE((*writer)->addFrame(image).ok());
  }
  EXPECT_TRUE((*writer)->finish().ok());
  return (*writer)->encoderDescription();
}

// The test movies: 10 frames of 64x48 at 30 frames/s, H.264, as read back by libavformat.
void expectTenFrames64x48At30Hz(const std::string& file) {
  auto info = readMovieInfo(file);
  ASSERT_TRUE(info.ok()) << info.error().format();
  EXPECT_EQ(info->frames, 10);
  EXPECT_EQ(info->width, 64u);
  EXPECT_EQ(info->height, 48u);
  EXPECT_NEAR(info->duration_s, 10.0 / 30.0, 1e-3);
  EXPECT_NEAR(info->frameRate_hz, 30.0, 1e-6);
  EXPECT_EQ(info->codec, "h264");
}

TEST(Mp4Writer, FramesSizeAndDurationReadBack) {
  TempDir dir("movie_writer");
  const std::string file = (dir / "gradient.mp4").string();
  EXPECT_EQ(writeGradient(file).rfind("libx264", 0), 0u);  // Debian's libavcodec has libx264
  expectTenFrames64x48At30Hz(file);
  // Deterministic: the same frames give the same bytes, whatever the heap held before (glibc fills
  // fresh allocations with the perturb byte: x264's AVX-512 code read such memory, issue 40 item 10).
  const std::string wide = (dir / "wide.mp4").string();
  writeGradient(wide, 320, 180);
  mallopt(M_PERTURB, 0x5a);
  writeGradient((dir / "again.mp4").string(), 320, 180);
  mallopt(M_PERTURB, 0xa5);
  writeGradient((dir / "third.mp4").string(), 320, 180);
  mallopt(M_PERTURB, 0);
  EXPECT_EQ(readFileBytes(wide), readFileBytes(dir / "again.mp4"));
  EXPECT_EQ(readFileBytes(wide), readFileBytes(dir / "third.mp4"));
  EXPECT_FALSE(Mp4Writer::open((dir / "odd.mp4").string(), 65, 48, 30).ok());
}

TEST(MovieFrames, CountAndNames) {
  EXPECT_EQ(movieFrameCount(0.3, 30), 10u);  // both ends: t = 0, 1/30, ..., 9/30
  EXPECT_EQ(movieFrameCount(20.0, 60), 1201u);
  EXPECT_EQ(movieFrameName(42, MovieFormat::png), "frame_000042.png");
  EXPECT_FALSE(isSupportedFrameRate(29, MovieFormat::mp4));
  EXPECT_TRUE(isSupportedFrameRate(30, MovieFormat::mp4));
  EXPECT_TRUE(isSupportedFrameRate(2, MovieFormat::png));  // a preview sequence
  EXPECT_TRUE(isSupportedFrameRate(29, MovieFormat::exr));
  EXPECT_FALSE(isSupportedFrameRate(0, MovieFormat::png));
  EXPECT_FALSE(isSupportedFrameRate(1001, MovieFormat::png));
}

class MovieTest : public testing::GpuTest {
 protected:
  // A 0.3 s descent over the plateau: 10 frames at 30 fps.
  CameraPath path() const {
    auto p = parseCameraPath(
        std::string(kCameraPathHeader) + "\n0 22.0 -98.5 3000 60 -20 0\n0.3 22.001 -98.499 2500 62 -19 0\n",
        "movie.path");
    EXPECT_TRUE(p.ok());
    return *p;
  }
  MovieSettings settings(const std::string& out, MovieFormat format) const {
    MovieSettings s;
    s.width = 64;
    s.height = 48;
    s.fps = 30;
    s.format = format;
    s.out = out;
    s.description = "movie_test";
    s.terrain = terrainSettingsFor(QualityPreset::kFast);
    return s;
  }
  PlanetDescription planet() const {
    return *loadPlanetFile(std::string(GLOBE_SOURCE_DIR) + "/assets/planets/earthlike.toml");
  }
};

TEST_F(MovieTest, PngSequenceIsDeterministicAndResumes) {
  TempDir dir("movie_png");
  const std::string a = (dir / "a").string(), b = (dir / "b").string();
  auto first = renderMovie(device(), planet(), path(), settings(a, MovieFormat::png));
  ASSERT_TRUE(first.ok()) << first.error().format();
  EXPECT_EQ(first->frames, 10u);
  EXPECT_EQ(first->rendered, 10u);
  auto second = renderMovie(device(), planet(), path(), settings(b, MovieFormat::png));
  ASSERT_TRUE(second.ok());
  for (uint64_t k = 0; k < 10; ++k)
    EXPECT_EQ(readFileBytes(fs::path(a) / movieFrameName(k, MovieFormat::png)),
              readFileBytes(fs::path(b) / movieFrameName(k, MovieFormat::png)))
        << "frame " << k;
  // The first and last frames differ: the camera moved.
  EXPECT_NE(readFileBytes(fs::path(a) / movieFrameName(0, MovieFormat::png)),
            readFileBytes(fs::path(a) / movieFrameName(9, MovieFormat::png)));

  fs::remove(fs::path(a) / movieFrameName(6, MovieFormat::png));
  auto resumed = renderMovie(device(), planet(), path(), settings(a, MovieFormat::png));
  ASSERT_TRUE(resumed.ok());
  EXPECT_EQ(resumed->rendered, 1u);
  EXPECT_EQ(resumed->kept, 9u);
  EXPECT_EQ(readFileBytes(fs::path(a) / movieFrameName(6, MovieFormat::png)),
            readFileBytes(fs::path(b) / movieFrameName(6, MovieFormat::png)));

  // Another movie's settings in the same directory are refused, nothing rendered.
  MovieSettings other = settings(a, MovieFormat::png);
  other.description = "another movie";
  EXPECT_FALSE(renderMovie(device(), planet(), path(), other).ok());
}

TEST_F(MovieTest, Mp4HasEveryFrame) {
  TempDir dir("movie_mp4");
  const std::string file = (dir / "descent.mp4").string();
  auto summary = renderMovie(device(), planet(), path(), settings(file, MovieFormat::mp4));
  ASSERT_TRUE(summary.ok()) << summary.error().format();
  EXPECT_FALSE(summary->encoder.empty());
  expectTenFrames64x48At30Hz(file);
  // Only the finished file is left: the temporary was renamed.
  int files = 0;
  for (const auto& e : fs::directory_iterator(fs::path(file).parent_path())) files += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1);
}

}  // namespace
}  // namespace globe
