#pragma once
// A one-line progress bar on stderr, redrawn in place with '\r', with the time left estimated from
// the rate so far. Drawn only when stderr is a terminal, so logs and test output stay clean.
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
  std::string label_;
  bool enabled_ = false;
  int last_percent_ = -1;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace globe::cli
