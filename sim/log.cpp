#include "sim/log.h"

#include <atomic>

namespace sim {
namespace {
std::atomic<LogLevel> g_threshold{LogLevel::Info};
}

LogLevel log_threshold() { return g_threshold.load(std::memory_order_relaxed); }
void set_log_threshold(LogLevel level) { g_threshold.store(level, std::memory_order_relaxed); }

void log_line(LogLevel level, std::string_view text) {
  static constexpr const char* kTag[] = {"debug", "info", "warning", "error"};
  std::fprintf(stderr, "vplant: %s: %.*s\n", kTag[static_cast<int>(level)], static_cast<int>(text.size()),
               text.data());
}

}  // namespace sim
