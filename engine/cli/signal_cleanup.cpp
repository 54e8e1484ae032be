#include "signal_cleanup.h"

#include <unistd.h>

#include <csignal>
#include <cstring>

namespace globe::cli {

namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
// A fixed buffer: the handler may only use async-signal-safe calls (unlink, signal, raise).
char g_path[4096] = {};

extern "C" void removeAndReraise(int sig) {
  if (g_path[0] != '\0') ::unlink(g_path);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

RemoveOnSignal::RemoveOnSignal(const std::string& path) {
  std::strncpy(g_path, path.c_str(), sizeof(g_path) - 1);
  for (int sig : kSignals) std::signal(sig, removeAndReraise);
}

RemoveOnSignal::~RemoveOnSignal() {
  for (int sig : kSignals) std::signal(sig, SIG_DFL);
  g_path[0] = '\0';
}

}  // namespace globe::cli
