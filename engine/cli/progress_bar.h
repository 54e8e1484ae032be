#pragma once
// A one-line progress bar on stderr, redrawn in place with '\r', with the time left estimated from
// the rate so far, when stderr is a terminal. Otherwise (a log, a batch job) a line every 30 s
// with the fraction done and the time left, so work that ends sooner prints nothing.
#include <chrono>
#include <string>

namespace globe {
class ElevationModel;
struct TerrainSettings;
}  // namespace globe

namespace globe::cli {

// On a terminal, says what the next long silent step is (the atmosphere tables' first build: ~20 s
// on lavapipe) before Terrain::create, when these settings draw the atmosphere and its tables are
// not cached yet.
void announceAtmosphereTables(const ElevationModel& model, const TerrainSettings& settings);

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar();  // finish()
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // fraction in [0, 1]; redraws at most once per percent.
  void update(double fraction);
  // Ends the line (if anything was drawn), so what is printed next starts on its own line.
  void finish();

 private:
  static constexpr std::chrono::seconds kLogInterval{30};
  void logLine(double fraction);  // not a terminal: a line per kLogInterval
  std::string label_;
  bool enabled_ = false;
  int last_percent_ = -1;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastLine_;
};

}  // namespace globe::cli
