#pragma once
// A one-line progress bar on stderr, redrawn in place with '\r'. Drawn only when stderr is a
// terminal, so logs and test output stay clean.
#include <string>

namespace globe::cli {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar();  // ends the line (if anything was drawn)
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // fraction in [0, 1]; redraws at most once per percent.
  void update(double fraction);

 private:
  std::string label_;
  bool enabled_ = false;
  int last_percent_ = -1;
};

}  // namespace globe::cli
