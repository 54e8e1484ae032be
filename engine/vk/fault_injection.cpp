#include "engine/vk/fault_injection.h"

#include <atomic>
#include <charconv>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>

namespace globe::vk {

namespace {

struct Fault {
  uint64_t at = 0;        // 1-based submit number that fails; 0: not armed
  bool andLater = false;  // every submit after it fails too
};

struct FaultPlan {
  Fault generation;  // counted over generation submits
  Fault deviceLost;  // counted over all submits
  uint64_t generationSubmits = 0;
  uint64_t allSubmits = 0;
  bool armed = false;
};

std::mutex planMutex;
FaultPlan plan;
std::atomic<int> planState{0};  // 0: GLOBE_FAULT not read yet, 1: nothing armed, 2: armed

Fault parseFault(std::string_view text, std::string_view item) {
  Fault f;
  f.andLater = !text.empty() && text.back() == '+';
  if (f.andLater) text.remove_suffix(1);
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), f.at);
  if (ec != std::errc() || end != text.data() + text.size() || f.at == 0)
    throw std::runtime_error("GLOBE_FAULT: expected KIND@N or KIND@N+ with N >= 1, got '" + std::string(item) + "'");
  return f;
}

FaultPlan parsePlan(const char* env) {
  FaultPlan p;
  std::string_view rest = env ? env : "";
  while (!rest.empty()) {
    const size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    const size_t at = item.find('@');
    const std::string_view kind = item.substr(0, at);
    const std::string_view count = at == std::string_view::npos ? std::string_view() : item.substr(at + 1);
    if (kind == "generation")
      p.generation = parseFault(count, item);
    else if (kind == "device-lost")
      p.deviceLost = parseFault(count, item);
    else
      throw std::runtime_error("GLOBE_FAULT: unknown fault '" + std::string(item) +
                               "' (generation@N[+], device-lost@N)");
  }
  p.deviceLost.andLater = p.deviceLost.at > 0;  // a lost device stays lost
  p.armed = p.generation.at > 0 || p.deviceLost.at > 0;
  return p;
}

bool hits(const Fault& f, uint64_t count) { return f.at > 0 && (count == f.at || (f.andLater && count > f.at)); }

}  // namespace

VkResult injectedSubmitFault(SubmitSite site) {
  int state = planState.load(std::memory_order_acquire);
  if (state == 1) return VK_SUCCESS;
  std::lock_guard<std::mutex> lock(planMutex);
  if (planState.load(std::memory_order_relaxed) == 0) {
    plan = parsePlan(std::getenv("GLOBE_FAULT"));
    planState.store(plan.armed ? 2 : 1, std::memory_order_release);
    if (!plan.armed) return VK_SUCCESS;
  }
  ++plan.allSubmits;
  if (hits(plan.deviceLost, plan.allSubmits)) return VK_ERROR_DEVICE_LOST;
  if (site == SubmitSite::kGeneration && hits(plan.generation, ++plan.generationSubmits))
    return VK_ERROR_OUT_OF_DEVICE_MEMORY;
  return VK_SUCCESS;
}

void resetFaultInjection() {
  std::lock_guard<std::mutex> lock(planMutex);
  plan = FaultPlan{};
  planState.store(0, std::memory_order_release);
}

}  // namespace globe::vk
