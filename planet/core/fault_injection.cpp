#include "planet/core/fault_injection.h"

#include <array>
#include <atomic>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>

namespace globe {

namespace {

constexpr std::array<std::string_view, 4> kKinds = {"generation", "device-lost", "fsync", "write"};
constexpr size_t kDeviceLost = 1;  // stays lost: every call after the first failing one fails too

struct Fault {
  uint64_t at = 0;        // 1-based call that fails; 0: not armed
  bool andLater = false;  // every later call fails too
  uint64_t calls = 0;
};

std::mutex planMutex;
std::array<Fault, kKinds.size()> plan;
std::atomic<int> planState{0};  // 0: GLOBE_FAULT not read yet, 1: nothing armed, 2: armed

Fault parseCount(std::string_view text, std::string_view item) {
  Fault f;
  f.andLater = !text.empty() && text.back() == '+';
  if (f.andLater) text.remove_suffix(1);
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), f.at);
  if (ec != std::errc() || end != text.data() + text.size() || f.at == 0)
    throw std::runtime_error("GLOBE_FAULT: expected KIND@N or KIND@N+ with N >= 1, got '" + std::string(item) + "'");
  return f;
}

bool readPlan() {
  plan = {};
  std::string_view rest = std::getenv("GLOBE_FAULT") ? std::getenv("GLOBE_FAULT") : "";
  bool armed = false;
  while (!rest.empty()) {
    const size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    const size_t at = item.find('@');
    size_t kind = 0;
    while (kind < kKinds.size() && kKinds[kind] != item.substr(0, at)) ++kind;
    if (kind == kKinds.size() || at == std::string_view::npos)
      throw std::runtime_error("GLOBE_FAULT: unknown fault '" + std::string(item) +
                               "' (generation@N[+], device-lost@N, fsync@N[+], write@N[+])");
    plan[kind] = parseCount(item.substr(at + 1), item);
    if (kind == kDeviceLost) plan[kind].andLater = true;
    armed = true;
  }
  return armed;
}

}  // namespace

bool injectFault(std::string_view kind) {
  if (planState.load(std::memory_order_acquire) == 1) return false;
  std::lock_guard<std::mutex> lock(planMutex);
  if (planState.load(std::memory_order_relaxed) == 0) planState.store(readPlan() ? 2 : 1, std::memory_order_release);
  for (size_t k = 0; k < kKinds.size(); ++k) {
    if (kKinds[k] != kind) continue;
    Fault& f = plan[k];
    ++f.calls;
    return f.at > 0 && (f.calls == f.at || (f.andLater && f.calls > f.at));
  }
  return false;
}

void resetFaultInjection() {
  std::lock_guard<std::mutex> lock(planMutex);
  planState.store(0, std::memory_order_release);
}

}  // namespace globe
