// Minimal diagnostics to stderr. Kept tiny on purpose: device and protocol code reports through
// return values and counters; this is only for operator-facing messages (link down, overruns).
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <string_view>

namespace sim {

enum class LogLevel { Debug, Info, Warn, Error };

LogLevel log_threshold();
void set_log_threshold(LogLevel level);
void log_line(LogLevel level, std::string_view text);

template <typename... Args>
void log(LogLevel level, fmt::format_string<Args...> f, Args&&... args) {
  if (level < log_threshold()) return;
  log_line(level, fmt::format(f, std::forward<Args>(args)...));
}

}  // namespace sim
