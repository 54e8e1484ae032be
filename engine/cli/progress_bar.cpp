#include "progress_bar.h"

#include "engine/atmosphere/atmosphere_luts.h"
#include "engine/render/terrain.h"
#include "planet/model/elevation_model.h"

#include <unistd.h>

#include <filesystem>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace globe::cli {

void announceAtmosphereTables(const ElevationModel& model, const TerrainSettings& settings) {
  if (::isatty(STDERR_FILENO) != 1 || settings.atmosphere == AtmosphereDetail::kOff || !model.atmosphere()) return;
  const std::string file = AtmosphereLuts::cacheFileFor(*model.atmosphere(), model.radius_m());
  std::error_code ec;
  if (std::filesystem::exists(file, ec)) return;
  std::fprintf(stderr, "computing the atmosphere's tables: once per atmosphere (~20 s on a CPU), then read from %s\n",
               file.c_str());
}

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)),
      enabled_(::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      lastLine_(start_) {}

namespace {
std::string timeLeft(double elapsed_s, double fraction) {
  if (!(fraction > 0 && fraction < 1)) return "";
  const long left_s = std::lround(elapsed_s * (1.0 - fraction) / fraction);
  char eta[32];
  std::snprintf(eta, sizeof(eta), " ETA %ld:%02ld", left_s / 60, left_s % 60);
  return eta;
}
}  // namespace

void ProgressBar::logLine(double fraction) {
  const auto now = std::chrono::steady_clock::now();
  if (now - lastLine_ < kLogInterval) return;
  lastLine_ = now;
  const double elapsed_s = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, "%s: %.1f%% after %ld:%02ld%s\n", label_.c_str(), std::clamp(fraction, 0.0, 1.0) * 100.0,
               std::lround(elapsed_s) / 60, std::lround(elapsed_s) % 60, timeLeft(elapsed_s, fraction).c_str());
  std::fflush(stderr);
}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::finish() {
  if (enabled_ && last_percent_ >= 0) std::fputc('\n', stderr);
  last_percent_ = -1;
  enabled_ = false;
  lastLine_ = std::chrono::steady_clock::time_point::max() - kLogInterval;  // no log line after the end
}

void ProgressBar::update(double fraction) {
  if (!enabled_) return logLine(fraction);
  fraction = std::clamp(fraction, 0.0, 1.0);
  const int percent = static_cast<int>(fraction * 100.0);
  if (percent == last_percent_) return;
  last_percent_ = percent;
  constexpr int kWidth = 40;
  const int filled = percent * kWidth / 100;
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, '.');
  // Time left at the average rate so far: total time scales as elapsed / fraction.
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "\r%s [%s] %3d%%%-12s", label_.c_str(), bar.c_str(), percent,
               timeLeft(elapsed_s, fraction).c_str());
  std::fflush(stderr);
}

}  // namespace globe::cli
