#pragma once
// Removes a temporary file when the process is interrupted (SIGINT, SIGTERM, SIGHUP), so that an
// export stopped with Ctrl-C leaves nothing behind; destructors do not run on a signal. SIGKILL
// cannot be caught: it can leave the hidden temporary (never the target).
#include <string>

namespace globe::cli {

class RemoveOnSignal {
 public:
  explicit RemoveOnSignal(const std::string& path);  // one at a time per process
  ~RemoveOnSignal();                                 // restores the default handlers
  RemoveOnSignal(const RemoveOnSignal&) = delete;
  RemoveOnSignal& operator=(const RemoveOnSignal&) = delete;
};

}  // namespace globe::cli
